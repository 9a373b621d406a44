#pragma once
// A project holding a rendered tunnel's visits, as the drive's tests need
// them (round starts, the office's rounds, the round's drawing): a straight
// alignment due north from the datum, chainage 0 to 200, a circular design,
// the tunnel's drive ascending. Each visit's 3D image is the design's
// outline rendered from where its walls start to its flat face
// (camera/synthetic_tunnel.h), already in the project frame (registered to
// monitoring targets: no range pole in view), with a stand-in photograph
// pair, placed at its face's chainage, given its heading (if any) and its
// date.
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

struct RenderedTunnelVisit {
  std::string label, heading;  // heading: empty for none
  camera::RenderedTunnelSpec spec;
  std::string started_at;      // ISO 8601, UTC
  std::string placement_note;  // the placement's note
  storage::RecordId id = 0;    // in the project made
};

struct RenderedTunnelProject {
  std::string name, tunnel_name;
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();
  double radius_m = 3.0;
};

// Makes the project at `file`; sets each visit's id.
inline void make_rendered_tunnel_project(const std::filesystem::path& file,
                                         const RenderedTunnelProject& project,
                                         std::vector<RenderedTunnelVisit>& visits) {
  storage::ProjectInfo info;
  info.name = project.name;
  info.datum = project.datum;
  {
    storage::ProjectStore store = storage::ProjectStore::create(file, info);
    storage::TunnelRecord tunnel;
    tunnel.name = project.tunnel_name;
    tunnel.stations = {{0, info.datum}, {200, info.datum + Eigen::Vector3d(0, 200, 0)}};
    tunnel.radii = {0};
    tunnel.profile = tunnel::circle_profile(project.radius_m);
    store.save_tunnel(tunnel);
    const tunnel::Alignment alignment = tunnel.alignment(info.datum);
    std::vector<unsigned char> png;
    cv::imencode(".png", cv::Mat(8, 8, CV_8UC3, cv::Scalar(90, 90, 90)), png);
    for (auto& v : visits) {
      v.id = store.begin_visit("tablet", v.label);
      storage::Model model;
      for (const auto& patch :
           camera::rendered_tunnel_patches(v.spec, alignment, tunnel.profile, v.label)) {
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
      placement.chainage = v.spec.face_chainage;
      placement.note = v.placement_note;
      store.save_visit_placement(placement);
      if (!v.heading.empty()) storage::save_visit_heading(store, v.id, v.heading);
    }
  }
  storage::sqlite::Connection db(file, storage::sqlite::Connection::Access::read_write);
  for (const auto& v : visits)
    db.exec(
        "UPDATE visit SET started_at = '" + v.started_at + "' WHERE id = " + std::to_string(v.id),
        "dating the test's visits");
}

}  // namespace rockface::test
