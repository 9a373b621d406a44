#pragma once
// A tunnel driven from both portals towards each other (issue 46: a round's
// earlier face is the previous face of its own heading): a straight
// alignment north from chainage 0 to 200, a circular design of 3 m radius,
// the tunnel's drive ascending. Each visit's 3D image is the design's
// outline rendered from where its walls start to its flat face
// (camera/synthetic_tunnel.h), already in the project frame (registered to
// monitoring targets: no range pole in view), and stored with its face's
// chainage as its placement, its heading and its date:
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

#include <opencv2/imgcodecs.hpp>

#include "camera/synthetic_tunnel.h"
#include "core/tunnel/design_profile.h"
#include "storage/project/project_sqlite.h"
#include "storage/project/project_store.h"
#include "storage/tunnel/visit_heading.h"

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
  storage::ProjectInfo info;
  info.name = "two headings";
  info.datum = {2600000, 1200000, 500};
  {
    storage::ProjectStore store = storage::ProjectStore::create(file, info);
    storage::TunnelRecord tunnel;
    tunnel.name = tunnel_name;
    tunnel.stations = {{0, info.datum}, {200, info.datum + Eigen::Vector3d(0, 200, 0)}};
    tunnel.radii = {0};
    tunnel.profile = tunnel::circle_profile(3.0);
    store.save_tunnel(tunnel);
    const tunnel::Alignment alignment = tunnel.alignment(info.datum);
    std::vector<unsigned char> png;
    cv::imencode(".png", cv::Mat(8, 8, CV_8UC3, cv::Scalar(90, 90, 90)), png);
    for (auto& v : visits) {
      v.id = store.begin_visit("tablet", v.label);
      camera::RenderedTunnelSpec spec;
      spec.chainage_from = v.walls_from;
      spec.face_chainage = v.face;
      // Coarse facets: only where the rounds start and end is read.
      spec.section_m = 0.5;
      spec.facet_m = 0.5;
      storage::Model model;
      for (const auto& patch :
           camera::rendered_tunnel_patches(spec, alignment, tunnel.profile, v.label)) {
        const int base = static_cast<int>(model.mesh.vertices.size());
        for (const auto& p : patch.polygon) model.mesh.vertices.push_back(p);
        for (int k = 1; k + 1 < static_cast<int>(patch.polygon.size()); ++k)
          model.mesh.faces.push_back({base, base + k, base + k + 1});
      }
      model.registration.kind = "ground_control";
      model.registration.rms_m = 0.005;
      model.registration.parameters_json = "{}";
      model.preset = "fast";
      storage::Capture capture;
      capture.visit_id = v.id;
      capture.label = v.label;
      capture.left.bytes = capture.right.bytes = png;
      model.capture_id = store.save_capture(capture);
      store.save_model(model);
      storage::VisitPlacement placement;
      placement.visit_id = v.id;
      placement.chainage = v.face;
      placement.note = "chainage " + std::to_string(v.face) + " typed";
      store.save_visit_placement(placement);
      if (!v.heading.empty()) storage::save_visit_heading(store, v.id, v.heading);
    }
  }
  storage::sqlite::Connection db(file, storage::sqlite::Connection::Access::read_write);
  for (const auto& v : visits)
    db.exec(
        "UPDATE visit SET started_at = '" + v.started_at + "' WHERE id = " + std::to_string(v.id),
        "dating the test's visits");
  return visits;
}

}  // namespace rockface::test
