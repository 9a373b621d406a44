#pragma once
// Where a round starts (issue 46): at the previous face of its own heading.
// A tunnel driven from more than one face — from the north and the south
// portal towards each other, a top heading with its bench behind it — has
// one alignment; a round of one heading starts where that heading's
// previous visit left its face, never at the nearest face of another
// heading. Visits without a heading are read among those without one, in
// the tunnel's drive direction (a tunnel with one face, as before headings
// existed).
//
// A named heading's direction is read from its own visits: a heading
// advances through the rock, so its faces' chainages grow or shrink with
// time (the sign of the trend of chainage against the visits' order by
// date). A heading with a single visit, or whose visits show no trend, is
// taken in the tunnel's drive direction: the one visit has no earlier face
// anyway, and the next visit shows which way it goes.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/tunnel/alignment.h"
#include "storage/project/project_store.h"

namespace rockface::app {

// A visit's stored face along the drive.
struct PlacedFace {
  storage::RecordId visit_id = 0;
  double chainage = 0;
  std::string heading;     // "" for none
  std::string started_at;  // the visit's start, as stored (ISO 8601 text)
};

struct DriveFaces {
  tunnel::Drive tunnel_drive = tunnel::Drive::ascending;
  std::vector<PlacedFace> faces;  // every stored placement
  // Every named visit's heading, placed or not (a visit placed by its
  // monitoring targets has no stored placement).
  std::map<storage::RecordId, std::string> headings;

  // "" when the visit has none.
  std::string heading_of(storage::RecordId visit_id) const;
  // +1 when the heading is driven toward ascending chainage, -1 descending.
  double sense_of(const std::string& heading) const;
  // The face a round of `visit_id` that ends at `round_to` starts from: the
  // nearest stored face of another visit of the same heading behind it in
  // `sense` (+1 / -1); none when no such visit lies behind. The round
  // starts there unless the 3D image starts farther on (visit_profile.h).
  std::optional<PlacedFace> previous_face(storage::RecordId visit_id, double round_to,
                                          double sense) const;
};

// Read from the project: its placements, headings and visits' dates;
// `tunnel_drive` the tunnel record's.
DriveFaces drive_faces(storage::ProjectStore& store, tunnel::Drive tunnel_drive);

}  // namespace rockface::app
