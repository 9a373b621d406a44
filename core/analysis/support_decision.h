#pragma once
// The round's support decision (issue 44): the class the geologist chose
// for the round, what rockface proposed, the changes made to the class with
// a reason for each, who decided and when. Stored with the visit
// (storage/project), synced to the office, printed in the field report and
// along the drive.
#include <string>
#include <vector>

namespace rockface::analysis {

// One change to the chosen class for this round ("bolt length", "3.0 m",
// "4.0 m", "wedge W2 needs 4 m").
struct SupportChange {
  std::string what, from, to, reason;
};

struct SupportDecision {
  std::string class_name;  // the class chosen
  std::string proposed;    // the class rockface proposed ("" none)
  std::vector<SupportChange> changes;
  std::string reason;      // why this class (required when it is not the proposed one)
  std::string decided_by;  // the geologist's name
  std::string decided_at;  // UTC, ISO 8601
  // The checks at the time of the decision, in words ("2 of 7 wedges below
  // FoS 1.5: W3 roof, W5 left wall"), so the record stands on its own.
  std::string checks;
};

}  // namespace rockface::analysis
