#pragma once
// The support along the drive (issue 44, `rockface drive --support-csv`):
// per placed visit, by chainage, its RMR89 and Q, the class the designer's
// classes propose from them and the class decided for the round (who,
// when). The wedge and behaviour criteria are not evaluated here (a wedge
// analysis per visit): a class that states them is proposed only in the
// visit's own `rockface support`.
#include <optional>
#include <string>
#include <vector>

#include "storage/project/project_store.h"

namespace rockface::app {

struct RoundSupport {
  storage::RecordId visit = 0;
  double chainage = 0;
  std::optional<double> rmr, q;
  std::string proposed, decided, decided_by, decided_at;
};

std::vector<RoundSupport> drive_support(storage::ProjectStore& store);
// "chainage_m,visit,rmr,q,proposed,decided,decided_by,decided_at"
std::string drive_support_csv(const std::vector<RoundSupport>& rounds);
// One line per round for the terminal.
std::vector<std::string> drive_support_summary(const std::vector<RoundSupport>& rounds);

}  // namespace rockface::app
