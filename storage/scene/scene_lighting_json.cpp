#include "storage/scene/scene_lighting_json.h"

namespace rockface::storage {

namespace {

using nlohmann::json;

SceneRegion read_region(const Reader& r, const json& v, const std::string& path,
                        const std::string& default_id) {
  SceneRegion region;
  region.id = default_id;
  if (auto* id = r.optional(v, path, "id")) {
    if (!id->is_string()) r.fail(path + ".id", "must be a string");
    region.id = id->get<std::string>();
  }
  const json& poly = r.array(r.require(v, path, "polygon"), path + ".polygon");
  if (poly.size() < 3) r.fail(path + ".polygon", "needs at least 3 points");
  for (std::size_t k = 0; k < poly.size(); ++k)
    region.polygon.push_back(r.vec3(poly[k], Reader::index(path + ".polygon", k)));
  return region;
}

// A strength given as a number, or `true` for the default.
std::optional<double> number_or_true(const Reader& r, const json& v, const std::string& path,
                                     double default_value) {
  if (v.is_boolean()) return v.get<bool>() ? std::optional<double>(default_value) : std::nullopt;
  return r.positive(v, path);
}

}  // namespace

void read_tunnel_lighting(const Reader& r, const json& ef, const std::string& ep,
                          SceneImagingEffects& out) {
  if (auto* v = r.optional(ef, ep, "flash")) {
    const std::string p = ep + ".flash";
    if (v->is_object()) {
      r.only_fields(*v, p, {"intensity"});
      out.flash = 1.0;
      if (auto* i = r.optional(*v, p, "intensity")) out.flash = r.positive(*i, p + ".intensity");
    } else
      out.flash = number_or_true(r, *v, p, 1.0);
  }
  if (auto* v = r.optional(ef, ep, "lamps")) {
    const json& lamps = r.array(*v, ep + ".lamps");
    for (std::size_t k = 0; k < lamps.size(); ++k) {
      const std::string p = Reader::index(ep + ".lamps", k);
      r.only_fields(lamps[k], p, {"position", "intensity"});
      SceneLamp lamp;
      lamp.position = r.vec3(r.require(lamps[k], p, "position"), p + ".position");
      lamp.intensity = r.positive(r.require(lamps[k], p, "intensity"), p + ".intensity");
      out.lamps.push_back(lamp);
    }
  }
  if (auto* v = r.optional(ef, ep, "vignetting")) {
    out.vignetting = number_or_true(r, *v, ep + ".vignetting", 1.0);
    if (out.vignetting && *out.vignetting > 4)
      r.fail(ep + ".vignetting", "strength above 4 blacks out most of the frame (1 = cos^4)");
  }
  if (auto* v = r.optional(ef, ep, "sensor")) {
    const std::string p = ep + ".sensor";
    r.only_fields(*v, p, {"iso", "base_iso", "full_well_e", "read_noise_e", "seed"});
    SceneSensor s;
    s.iso = r.number_in(r.require(*v, p, "iso"), p + ".iso", 25, 409600, false);
    if (auto* x = r.optional(*v, p, "base_iso")) s.base_iso = r.positive(*x, p + ".base_iso");
    if (auto* x = r.optional(*v, p, "full_well_e"))
      s.full_well_e = r.positive(*x, p + ".full_well_e");
    if (auto* x = r.optional(*v, p, "read_noise_e"))
      s.read_noise_e = r.non_negative(*x, p + ".read_noise_e");
    if (auto* x = r.optional(*v, p, "seed")) {
      const int seed = r.integer(*x, p + ".seed");
      if (seed < 0) r.fail(p + ".seed", "must not be negative");
      s.seed = static_cast<unsigned>(seed);
    }
    if (s.iso < s.base_iso) r.fail(p + ".iso", "is below base_iso; the sensor has no such gain");
    out.sensor = s;
  }
  if (auto* v = r.optional(ef, ep, "jpeg_quality")) {
    out.jpeg_quality = r.integer(*v, ep + ".jpeg_quality");
    if (*out.jpeg_quality < 1 || *out.jpeg_quality > 100)
      r.fail(ep + ".jpeg_quality", "must be between 1 and 100");
  }
  if (auto* v = r.optional(ef, ep, "wet")) {
    const json& wet = r.array(*v, ep + ".wet");
    for (std::size_t k = 0; k < wet.size(); ++k) {
      const std::string p = Reader::index(ep + ".wet", k);
      r.only_fields(wet[k], p, {"id", "polygon", "specular", "shininess", "darkening"});
      SceneWet w;
      w.region = read_region(r, wet[k], p, "W" + std::to_string(k + 1));
      if (auto* x = r.optional(wet[k], p, "specular"))
        w.specular = r.number_in(*x, p + ".specular", 0, 10, false);
      if (auto* x = r.optional(wet[k], p, "shininess"))
        w.shininess = r.number_in(*x, p + ".shininess", 1, 10000, false);
      if (auto* x = r.optional(wet[k], p, "darkening"))
        w.darkening = r.number_in(*x, p + ".darkening", 0, 1, false);
      out.wet.push_back(w);
    }
  }
  if (auto* v = r.optional(ef, ep, "shotcrete")) {
    const json& sc = r.array(*v, ep + ".shotcrete");
    for (std::size_t k = 0; k < sc.size(); ++k) {
      const std::string p = Reader::index(ep + ".shotcrete", k);
      r.only_fields(sc[k], p, {"id", "polygon", "albedo"});
      SceneShotcrete s;
      s.region = read_region(r, sc[k], p, "S" + std::to_string(k + 1));
      if (auto* x = r.optional(sc[k], p, "albedo"))
        s.albedo = r.number_in(*x, p + ".albedo", 0, 1, false);
      out.shotcrete.push_back(s);
    }
  }
  if (auto* v = r.optional(ef, ep, "dust")) {
    const std::string p = ep + ".dust";
    r.only_fields(*v, p, {"beta_per_m", "visibility_m", "airlight"});
    SceneDust d;
    const json* beta = r.optional(*v, p, "beta_per_m");
    const json* visibility = r.optional(*v, p, "visibility_m");
    if ((beta == nullptr) == (visibility == nullptr))
      r.fail(p, "give one of beta_per_m (extinction, 1/m) or visibility_m (metres)");
    // Koschmieder's visibility: where a black object's contrast falls to 2 %.
    d.beta_per_m = beta ? r.positive(*beta, p + ".beta_per_m")
                        : 3.912 / r.positive(*visibility, p + ".visibility_m");
    if (auto* x = r.optional(*v, p, "airlight"))
      d.airlight = r.number_in(*x, p + ".airlight", 0, 1, false);
    out.dust = d;
  }
}

}  // namespace rockface::storage
