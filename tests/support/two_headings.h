#pragma once
// A tunnel driven from both portals towards each other (issue 46: a round's
// earlier face is the previous face of its own heading): a straight
// alignment north from chainage 0 to 200, a circular design of 3 m radius,
// the tunnel's drive ascending; each visit made as
// rendered_tunnel_project.h makes it:
//
//   N1  North portal  walls 100 → face 104  2026-03-02 08:00
//   S1  South portal  walls 128 → face 124  2026-03-02 14:00
//   N2  North portal  walls 102 → face 108  2026-03-03 08:00
//   S2  South portal  walls 126 → face 120  2026-03-03 14:00
//   U1  (none)        walls 100 → face 116  2026-03-04 08:00
//
// The truth by construction: N2's round starts at N1's face (104), S2's at
// S1's (124, the south heading advancing toward descending chainage), and
// N1, S1 and U1 have no earlier face of their own heading (U1 is the only
// visit without one), so their rounds start where their walls start.
#include <filesystem>
#include <string>
#include <vector>

#include "storage/project/project_store.h"
#include "tests/support/rendered_tunnel_project.h"

namespace rockface::test {

struct HeadingVisit {
  std::string label, heading;
  double walls_from = 0, face = 0;
  std::string started_at;
  storage::RecordId id = 0;  // in the project made
};

inline std::vector<HeadingVisit> two_headings_visits() {
  return {{"N1", "North portal", 100, 104, "2026-03-02T08:00:00Z"},
          {"S1", "South portal", 128, 124, "2026-03-02T14:00:00Z"},
          {"N2", "North portal", 102, 108, "2026-03-03T08:00:00Z"},
          {"S2", "South portal", 126, 120, "2026-03-03T14:00:00Z"},
          {"U1", "", 100, 116, "2026-03-04T08:00:00Z"}};
}

// Makes the project at `file` (its tunnel named `tunnel`); the visits with
// their ids.
inline std::vector<HeadingVisit> make_two_headings_project(const std::filesystem::path& file,
                                                           const std::string& tunnel_name) {
  std::vector<HeadingVisit> visits = two_headings_visits();
  std::vector<RenderedTunnelVisit> rendered;
  for (const auto& v : visits) {
    RenderedTunnelVisit r;
    r.label = v.label;
    r.heading = v.heading;
    r.spec.chainage_from = v.walls_from;
    r.spec.face_chainage = v.face;
    // Coarse facets: only where the rounds start and end is read.
    r.spec.section_m = 0.5;
    r.spec.facet_m = 0.5;
    r.started_at = v.started_at;
    r.placement_note = "chainage " + std::to_string(v.face) + " typed";
    rendered.push_back(r);
  }
  make_rendered_tunnel_project(file, {"two headings", tunnel_name, {2600000, 1200000, 500}, 3.0},
                               rendered);
  for (std::size_t i = 0; i < visits.size(); ++i) visits[i].id = rendered[i].id;
  return visits;
}

}  // namespace rockface::test
