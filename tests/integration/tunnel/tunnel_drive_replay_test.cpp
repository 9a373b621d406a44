// Five visits along the rendered tunnel, 2.5 m apart, each replayed through
// the mock camera with its traces picked in the left photograph (where the
// joints cross the face, as a geologist taps them), so every plane of the
// drive is measured on a reconstructed face. One set turns by 20 degrees
// over the 10 m, one is steady, one appears in the last two visits; the
// sets carry no names the drive could match them by (each visit's joints
// are named afresh).
#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/calib3d.hpp>

#include "camera/synthetic_renderer.h"
#include "core/common/progress.h"
#include "core/geometry/orientation.h"
#include "firmware-app/render/synthetic_scene_from_scene.h"
#include "firmware-app/replay/field_replay.h"
#include "firmware-app/tunnel/project_drive.h"
#include "storage/project/project_store.h"
#include "storage/scene/scene.h"
#include "tests/support/test_paths.h"
#include "tests/support/tunnel_drive_scene.h"

namespace rockface::app {
namespace {

namespace fs = std::filesystem;
using Eigen::Vector3d;
using nlohmann::json;

constexpr double kE = 512340.0, kN = 5211800.0, kZ = 410.0;
json at(double chainage, double offset, double v) {
  return {kE + offset, kN + chainage, kZ + v};
}

// The face's traces in the left photograph: each joint's pieces on the
// face's quarters chained into one polyline, projected, kept inside the
// image, thinned to a dozen taps. A trace must bend (two quarters or more)
// for its plane to be measured from it.
json face_picks(const storage::Scene& scene) {
  const SyntheticSceneInput in = synthetic_scene_from_scene(scene);
  const photogrammetry::CameraIntrinsics k = camera::rendered_intrinsics(in.scene);
  const photogrammetry::CameraPose pose = camera::station_pose(in.scene.stations[0], "left");
  cv::Mat R(3, 3, CV_64F), rvec;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R.at<double>(i, j) = pose.R(i, j);
  cv::Rodrigues(R, rvec);
  const Vector3d t = pose.translation();
  const cv::Mat tvec = (cv::Mat_<double>(3, 1) << t.x(), t.y(), t.z());
  const cv::Mat K = (cv::Mat_<double>(3, 3) << k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1);
  const cv::Mat dist(1, 5, CV_64F, const_cast<double*>(k.distortion.data()));
  // The range pole stands in front of the face: a geologist does not tap
  // on it, so taps within 30 px of its image are left out.
  std::vector<cv::Point2d> pole_px;
  if (in.scene.range_pole) {
    const Vector3d b = in.scene.range_pole->base;
    std::vector<cv::Point3d> ends{{b.x(), b.y(), b.z() - 1.0},
                                  {b.x(), b.y(), b.z() + in.scene.range_pole->length + 0.3}};
    cv::projectPoints(ends, rvec, tvec, K, dist, pole_px);
  }
  auto near_pole = [&](const cv::Point2d& p) {
    if (pole_px.size() != 2) return false;
    const cv::Point2d d = pole_px[1] - pole_px[0];
    const double t = std::clamp((p - pole_px[0]).dot(d) / d.dot(d), 0.0, 1.0);
    const cv::Point2d q = pole_px[0] + t * d;
    return std::hypot(p.x - q.x, p.y - q.y) < 30;
  };
  std::map<std::string, std::vector<std::array<Vector3d, 2>>> pieces;
  for (const auto& seg : camera::true_trace_segments(in.scene))
    if (seg.patch.rfind("FACE", 0) == 0) pieces[seg.joint].push_back(seg.world);
  json traces = json::array();
  for (auto& [joint, segs] : pieces) {
    if (segs.size() < 2) continue;
    // Chain the pieces end to end (they meet where the quarters do).
    std::vector<Vector3d> chain{segs[0][0], segs[0][1]};
    std::vector<bool> used(segs.size(), false);
    used[0] = true;
    for (bool grew = true; grew;) {
      grew = false;
      for (std::size_t i = 0; i < segs.size(); ++i) {
        if (used[i]) continue;
        for (int end = 0; end < 2 && !used[i]; ++end) {
          const Vector3d& a = segs[i][end];
          const Vector3d& b = segs[i][1 - end];
          if ((a - chain.back()).norm() < 1e-6) {
            chain.push_back(b);
          } else if ((a - chain.front()).norm() < 1e-6) {
            chain.insert(chain.begin(), b);
          } else {
            continue;
          }
          used[i] = grew = true;
        }
      }
    }
    if (chain.size() < 3) continue;
    std::vector<cv::Point3d> dense;
    for (std::size_t i = 0; i + 1 < chain.size(); ++i)
      for (int s = 0; s < 20; ++s) {
        const Vector3d x = chain[i] + (chain[i + 1] - chain[i]) * (s / 20.0);
        dense.emplace_back(x.x(), x.y(), x.z());
      }
    std::vector<cv::Point2d> px;
    cv::projectPoints(dense, rvec, tvec, K, dist, px);
    std::vector<cv::Point2d> inside;
    for (const auto& p : px)
      if (p.x > 15 && p.y > 15 && p.x < k.width - 15 && p.y < k.height - 15 && !near_pole(p))
        inside.push_back(p);
    if (inside.size() < 12) continue;
    json pixels = json::array();
    for (int s = 0; s < 12; ++s) {
      const auto& p = inside[s * (inside.size() - 1) / 11];
      pixels.push_back({std::round(p.x * 10) / 10, std::round(p.y * 10) / 10});
    }
    traces.push_back({{"id", "T" + std::to_string(traces.size() + 1)},
                      {"joint", joint},
                      {"photo", "left"},
                      {"pixels", pixels}});
  }
  return {{"traces", traces}};
}

json visit_scene(int v) {
  json s = test::tunnel_drive_scene();
  const double face = 102.0 + 2.5 * v;
  s["tunnel"]["placement"] = {{"chainage", face - 1.4}, {"offset", 1.3}, {"height", -1.05}};
  s["tunnel"]["render"] = {{"from_chainage", face - 12},
                           {"face_chainage", face},
                           {"section_m", 0.25},
                           {"facet_m", 0.1},
                           {"face_relief_m", 1.0}};
  auto& im = s["imaging"];
  im["camera"] = {{"width", 900},
                  {"height", 600},
                  {"fx", 600.0},
                  {"fy", 600.0},
                  {"cx", 449.5},
                  {"cy", 299.5},
                  {"distortion", {-0.05, 0.02, 0, 0, 0}}};
  im["stations"] =
      json::array({{{"position", at(face - 7, -0.6, 0.2)}, {"look_at", at(face, 0, 0.9)}},
                   {{"position", at(face - 7, 0.6, 0.2)}, {"look_at", at(face, 0, 0.9)}}});
  im["range_pole"] = {
      {"base", at(face - 1.4, 1.3, -1.05)}, {"length", 2.0}, {"target_diameter", 0.25}};
  im["reference_line"] = {{"from", at(face, -1.5, 0)}, {"to", at(face, 1.5, 0)}};
  im["texture_seed"] = 20 + v;
  // Three sets: one turning 5 degrees a visit, one steady, one from the
  // fourth visit; parallel joints 0.9 m apart through the face.
  json joints = json::array();
  auto set = [&](const std::string& prefix, double dip, double dipdir, int count, double friction) {
    const Vector3d n = geometry::plane_normal_deg(dip, dipdir);
    for (int j = 0; j < count; ++j) {
      const double along = 0.9 * (j - (count - 1) / 2.0);
      const json p = at(face - 0.3, 0.2 * j, 0.4);
      joints.push_back({{"id", prefix + std::to_string(j + 1)},
                        {"dip", dip},
                        {"dipdir", dipdir},
                        {"point",
                         {p[0].get<double>() + along * n.x(), p[1].get<double>() + along * n.y(),
                          p[2].get<double>() + along * n.z()}},
                        {"friction", friction},
                        {"cohesion", 0}});
    }
  };
  set("A", 60, 200 + 5.0 * v, 3, 32);
  set("B", 75, 110, 3, 30);
  if (v >= 3) set("C", 35, 330, 2, 28);
  s["joints"] = joints;
  s.erase("free_faces");
  s["analysis"]["pyramids"] = false;
  s["analysis"]["rotation"] = false;
  return s;
}

TEST(TunnelDriveReplay, FiveReplayedVisitsFindTheTurnAndTheNewSet) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-tunnel-drive-replay-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path project = dir / "drive.rockface";
  std::vector<double> faces;
  for (int v = 0; v < 5; ++v) {
    json s = visit_scene(v);
    const fs::path file = dir / ("visit" + std::to_string(v) + ".scene.json");
    std::ofstream(file) << s.dump();
    s["picks"] = face_picks(storage::load_scene(file.string()));
    ASSERT_GE(s["picks"]["traces"].size(), 4u) << "visit " << v << ": too few traces to pick";
    std::ofstream(file) << s.dump();
    NoProgress quiet;
    const ReplayOutcome out =
        replay_field_workflow({file.string(), project.string(), Preset::fast, {}, {}, {}}, quiet);
    storage::ProjectStore store = storage::ProjectStore::open(project);
    const auto placed = store.load_visit_placement(out.visit_id);
    ASSERT_TRUE(placed);
    faces.push_back(placed->chainage);
  }
  storage::ProjectStore store = storage::ProjectStore::open(project);
  const tunnel::DriveSets drive = project_drive(store);
  ASSERT_EQ(drive.visits.size(), 5u);
  for (const auto& line : drive_summary(drive, drive_geologists(store))) std::cout << line << "\n";
  const tunnel::SetTrack* turning = nullptr;
  const tunnel::SetTrack* fresh = nullptr;
  for (const auto& t : drive.tracks) {
    const auto& first = t.points.front();
    if (std::abs(first.dip_deg - 60) < 8 && std::abs(first.dipdir_deg - 200) < 8) turning = &t;
    if (t.appears) fresh = &t;
    // The steady set (75/110) never turns.
    if (std::abs(first.dip_deg - 75) < 8 && std::abs(first.dipdir_deg - 110) < 8) {
      EXPECT_FALSE(t.turns);
    }
  }
  ASSERT_NE(turning, nullptr) << "the 60/200 set was not tracked";
  ASSERT_NE(fresh, nullptr) << "no set appears along the drive";
  // The turning set is one track through all five visits (matched across a
  // 5 degree step), and its turn is flagged after the first visit and by
  // the fourth (20 degrees then; the measured cones are a few degrees).
  EXPECT_EQ(turning->points.size(), 5u);
  ASSERT_TRUE(turning->turns);
  double first_turn = 1e9;
  for (const auto& e : turning->events)
    if (e.kind == tunnel::TrackEvent::Kind::turns) first_turn = std::min(first_turn, e.chainage);
  // The set turns from the first visit on, 5 degrees a step; the measured
  // cones (alpha95 of three planes, 1-2 degrees each) are well inside that,
  // so the turn is found at the second visit.
  EXPECT_NEAR(first_turn, faces[1], 1e-9);
  // The new set appears at the fourth visit, and it is the 35/330 set: its
  // planes come from two traces each on a face whose quarters differ by
  // ~10 degrees, so each is known to ~10-15 degrees about its trace line:
  // its mean lies within 20 degrees of the truth.
  EXPECT_NEAR(fresh->points.front().chainage, faces[3], 1e-9);
  const double angle = std::acos(
      std::min(1.0, std::abs(fresh->mean_normal.dot(geometry::plane_normal_deg(35, 330)))));
  EXPECT_LT(angle * 180 / M_PI, 20.0);
  EXPECT_EQ(fresh->points.size(), 2u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rockface::app
