// The scene's `tunnel` section: what a scene gets when it leaves fields out,
// and each bad field refused by its path.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "storage/scene/scene.h"
#include "tests/support/test_paths.h"

namespace rockface::storage {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json minimal_tunnel() {
  const fs::path samples = fs::path(ROCKFACE_SOURCE_DIR) / "tools/samples";
  return {{"alignment", (samples / "tunnel-drive.alignment.csv").string()},
          {"profile", (samples / "tunnel-drive.profile.json").string()}};
}

Scene scene_with(const json& tunnel) {
  const json doc = {{"format", "rockface-scene/1"}, {"tunnel", tunnel}};
  return parse_scene(doc.dump(), "t.scene.json");
}

void expect_refused(const json& tunnel, const std::string& field) {
  try {
    scene_with(tunnel);
    FAIL() << "accepted a bad " << field;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

TEST(SceneTunnel, DefaultsWhenFieldsAreLeftOut) {
  const Scene s = scene_with(minimal_tunnel());
  ASSERT_TRUE(s.tunnel);
  EXPECT_EQ(s.tunnel->record.drive, tunnel::Drive::ascending);
  EXPECT_DOUBLE_EQ(s.tunnel->record.underbreak_tolerance_m, 0.05);
  EXPECT_FALSE(s.tunnel->placement);  // the pole's surveyed position then
  EXPECT_FALSE(s.tunnel->render);     // nothing rendered
  EXPECT_EQ(s.tunnel->record.stations.size(), 3u);
  EXPECT_NEAR(s.tunnel->record.profile.perimeter(), 19.32, 0.01);
}

TEST(SceneTunnel, BadFieldsAreRefusedByTheirPath) {
  json t = minimal_tunnel();
  t["drive"] = "sideways";
  expect_refused(t, "tunnel.drive");
  t = minimal_tunnel();
  t["alignment"] = "no-such-file.csv";
  expect_refused(t, "no-such-file.csv");
  t = minimal_tunnel();
  t["underbreak_tolerance_m"] = -0.1;
  expect_refused(t, "tunnel.underbreak_tolerance_m");
  t = minimal_tunnel();
  t["placement"] = json::object();
  expect_refused(t, "tunnel.placement.chainage");
  t = minimal_tunnel();
  t["render"] = {{"from_chainage", 100}, {"face_chainage", 100}};
  expect_refused(t, "tunnel.render.face_chainage");
  t = minimal_tunnel();
  t["render"] = {{"from_chainage", 100},
                 {"face_chainage", 112},
                 {"breaks", {{{"chainage", {108, 107}}, {"s", {1, 2}}, {"depth_m", 0.2}}}}};
  expect_refused(t, "tunnel.render.breaks[0].chainage");
  t = minimal_tunnel();
  t["profile"] = {{"segments", json::array()}};
  expect_refused(t, "tunnel.profile");
}

}  // namespace
}  // namespace rockface::storage
