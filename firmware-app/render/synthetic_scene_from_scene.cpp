#include "firmware-app/render/synthetic_scene_from_scene.h"

#include "core/common/error.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "firmware-app/tunnel/rendered_tunnel.h"

namespace rockface::app {

namespace {

// The tunnel lighting of the scene (absolute positions) in the render's
// datum-relative frame.
void tunnel_lighting_from_scene(const storage::SceneImagingEffects& in,
                                const Eigen::Vector3d& origin, camera::SyntheticEffects& out) {
  auto region = [&](const storage::SceneRegion& r) {
    camera::SyntheticRegion s{r.id, {}};
    for (const auto& x : r.polygon) s.polygon.push_back(x - origin);
    return s;
  };
  if (in.flash) out.flash = camera::SyntheticFlash{*in.flash};
  for (const auto& l : in.lamps) out.lamps.push_back({l.position - origin, l.intensity});
  out.vignetting = in.vignetting;
  if (in.sensor)
    out.sensor =
        camera::SyntheticSensor{in.sensor->iso, in.sensor->base_iso, in.sensor->full_well_e,
                                in.sensor->read_noise_e, in.sensor->seed};
  out.jpeg_quality = in.jpeg_quality;
  for (const auto& w : in.wet)
    out.wet.push_back({region(w.region), w.specular, w.shininess, w.darkening});
  for (const auto& s : in.shotcrete) out.shotcrete.push_back({region(s.region), s.albedo});
  if (in.dust) out.dust = camera::SyntheticDust{in.dust->beta_per_m, in.dust->airlight};
}

}  // namespace

SyntheticSceneInput synthetic_scene_from_scene(const storage::Scene& s) {
  if (!s.imaging)
    throw InputError(s.source + ": imaging",
                     "missing: only a scene with an imaging section can be rendered");
  const bool tunnel = s.tunnel && s.tunnel->render;
  if (s.patches.empty() && !tunnel)
    throw InputError(s.source + ": surface.patches",
                     "missing: the scene has no surface for the cameras to see");
  SyntheticSceneInput in;
  // Render in datum-relative coordinates: survey coordinates of 10^6 m would
  // lose millimetres in single-precision depth.
  in.origin = s.has_datum ? s.datum : Eigen::Vector3d::Zero();
  camera::SyntheticScene& out = in.scene;
  if (tunnel) {
    // The round as excavated replaces the scene's patches: walls, roof,
    // invert and face of the design profile with the known breaks.
    out.patches = camera::rendered_tunnel_patches(
        rendered_tunnel_spec(*s.tunnel->render), s.tunnel->record.alignment(in.origin),
        s.tunnel->record.profile, s.source + ": tunnel.render");
  } else
    for (const auto& p : s.patches) {
      camera::SyntheticPatch patch{p.id, {}};
      for (const auto& x : p.polygon) patch.polygon.push_back(x - in.origin);
      out.patches.push_back(std::move(patch));
    }
  for (const auto& j : s.joints) {
    if (!j.point) continue;  // orientation-only joints cut no trace
    out.joints.push_back({j.id, geometry::plane_normal_deg(j.dip, j.dipdir), *j.point - in.origin});
  }
  const auto& im = *s.imaging;
  auto& c = out.camera;
  c.width = im.camera.width;
  c.height = im.camera.height;
  c.fx = im.camera.fx;
  c.fy = im.camera.fy;
  c.cx = im.camera.cx;
  c.cy = im.camera.cy;
  c.distortion = im.camera.distortion;
  for (std::size_t k = 0; k + 1 < im.stations.size(); k += 2) {
    std::array<camera::SyntheticStation, 2> pair;
    for (std::size_t side = 0; side < 2; ++side)
      pair[side] = {im.stations[k + side].position - in.origin,
                    im.stations[k + side].look_at - in.origin};
    in.pairs.push_back(pair);
  }
  out.stations = in.pairs.front();
  if (im.range_pole)
    out.range_pole = camera::SyntheticRangePole{
        im.range_pole->base - in.origin, im.range_pole->length, im.range_pole->target_diameter};
  if (im.reference_line)
    out.reference_line =
        std::make_pair(im.reference_line->first - in.origin, im.reference_line->second - in.origin);
  for (const auto& t : im.control_targets)
    out.control_targets.push_back({t.id, t.position - in.origin, t.diameter});
  out.effects.distortion = im.effects.distortion;
  out.effects.noise_sigma = im.effects.noise_sigma;
  out.effects.blur_px = im.effects.blur_px;
  out.effects.exposure = im.effects.exposure;
  tunnel_lighting_from_scene(im.effects, in.origin, out.effects);
  out.texture_seed = im.texture_seed;
  return in;
}

}  // namespace rockface::app
