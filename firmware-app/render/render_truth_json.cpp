#include "firmware-app/render/render_truth_json.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/common/units.h"

namespace rockface::app {

using json = nlohmann::json;

namespace {

json truth_vec(const Eigen::Vector3d& v) {
  return json::array({v.x(), v.y(), v.z()});
}
json pixel(const Eigen::Vector2d& p) {
  return json::array({p.x(), p.y()});
}

// The tunnel lighting the render used, positions absolute again.
void add_tunnel_lighting(json& out, const camera::SyntheticEffects& e,
                         const Eigen::Vector3d& origin) {
  auto region = [&](const camera::SyntheticRegion& r) {
    json poly = json::array();
    for (const auto& x : r.polygon) poly.push_back(truth_vec(x + origin));
    return json{{"id", r.id}, {"polygon", poly}};
  };
  if (e.flash) out["flash"] = {{"intensity", e.flash->intensity}};
  for (const auto& l : e.lamps)
    out["lamps"].push_back(
        {{"position", truth_vec(l.position + origin)}, {"intensity", l.intensity}});
  if (e.vignetting) out["vignetting"] = *e.vignetting;
  if (e.sensor)
    out["sensor"] = {{"iso", e.sensor->iso},
                     {"base_iso", e.sensor->base_iso},
                     {"full_well_e", e.sensor->full_well_e},
                     {"read_noise_e", e.sensor->read_noise_e},
                     {"seed", e.sensor->seed}};
  if (e.jpeg_quality) out["jpeg_quality"] = *e.jpeg_quality;
  for (const auto& w : e.wet) {
    json j = region(w.region);
    j["specular"] = w.specular;
    j["shininess"] = w.shininess;
    j["darkening"] = w.darkening;
    out["wet"].push_back(j);
  }
  for (const auto& s : e.shotcrete) {
    json j = region(s.region);
    j["albedo"] = s.albedo;
    out["shotcrete"].push_back(j);
  }
  if (e.dust)
    out["dust"] = {{"beta_per_m", e.dust->beta_per_m},
                   {"visibility_m", 3.912 / e.dust->beta_per_m},
                   {"airlight", e.dust->airlight}};
}

}  // namespace

std::string render_truth_json(const camera::SyntheticScene& scene, const camera::SyntheticRender& r,
                              const Eigen::Vector3d& origin, const std::string& scene_name) {
  json doc = json::object();
  doc["format"] = "rockface-render-truth/1";
  doc["scene"] = scene_name;
  doc["datum"] = truth_vec(origin);
  const auto& c = r.intrinsics;
  doc["intrinsics"] = {
      {"width", c.width}, {"height", c.height},        {"fx", c.fx}, {"fy", c.fy}, {"cx", c.cx},
      {"cy", c.cy},       {"distortion", c.distortion}};
  const char* names[2] = {"left", "right"};
  json cameras = json::array();
  for (int s = 0; s < 2; ++s) {
    json rotation = json::array();
    for (int i = 0; i < 3; ++i)
      rotation.push_back(json::array({r.poses[s].R(i, 0), r.poses[s].R(i, 1), r.poses[s].R(i, 2)}));
    cameras.push_back({{"station", names[s]},
                       {"position", truth_vec(r.poses[s].centre + origin)},
                       {"look_at", truth_vec(scene.stations[s].look_at + origin)},
                       {"rotation_world_to_camera", rotation},
                       {"image", std::string(names[s]) + ".png"}});
  }
  doc["cameras"] = cameras;
  if (scene.range_pole) {
    doc["range_pole"] = {{"base", truth_vec(scene.range_pole->base + origin)},
                         {"length", scene.range_pole->length},
                         {"target_diameter", scene.range_pole->target_diameter},
                         {"target_design",
                          "black disk of the target diameter with a white disk of half that "
                          "diameter; the disk faces the midpoint of the two stations"}};
    json targets = json::array();
    const char* ids[2] = {"lower", "upper"};
    for (size_t t = 0; t < r.targets.size(); ++t) {
      const auto& target = r.targets[t];
      targets.push_back({{"id", ids[t % 2]},
                         {"centre", truth_vec(target.centre + origin)},
                         {"normal", truth_vec(target.normal)},
                         {"left", pixel(target.image[0])},
                         {"right", pixel(target.image[1])},
                         {"visible", json::array({target.visible[0], target.visible[1]})}});
    }
    doc["targets"] = targets;
  }
  if (scene.reference_line) {
    const Eigen::Vector3d d = scene.reference_line->second - scene.reference_line->first;
    double azimuth = rad_to_deg(std::atan2(d.x(), d.y()));
    if (azimuth < 0) azimuth += 360;
    json line = {{"from", truth_vec(scene.reference_line->first + origin)},
                 {"to", truth_vec(scene.reference_line->second + origin)},
                 {"azimuth_deg", azimuth}};
    if (r.reference_line_left)
      line["left"] =
          json::array({pixel((*r.reference_line_left)[0]), pixel((*r.reference_line_left)[1])});
    doc["reference_line"] = line;
  }
  json traces = json::array();
  for (const auto& t : r.traces) {
    json left = json::array();
    for (const auto& p : t.left_image) left.push_back(pixel(p));
    traces.push_back(
        {{"joint", t.joint},
         {"patch", t.patch},
         {"world", json::array({truth_vec(t.world[0] + origin), truth_vec(t.world[1] + origin)})},
         {"left_image", left}});
  }
  doc["traces"] = traces;
  doc["depth"] = {{"file", "depth-left.pfm"},
                  {"units", "m"},
                  {"measured_along", "optical axis of the left camera"},
                  {"nothing_hit", 0}};
  doc["effects"] = {{"distortion", scene.effects.distortion},
                    {"noise_sigma", scene.effects.noise_sigma},
                    {"blur_px", scene.effects.blur_px},
                    {"exposure", scene.effects.exposure}};
  add_tunnel_lighting(doc["effects"], scene.effects, origin);
  doc["effects_simulated"] = scene.effects.simulated();
  doc["texture_seed"] = scene.texture_seed;
  return doc.dump(2) + "\n";
}

}  // namespace rockface::app
