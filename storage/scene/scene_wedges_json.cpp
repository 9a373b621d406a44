// The scene's `wedges` section.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/tunnel/support_ranges.h"
#include "core/tunnel/survey_ranges.h"
#include "storage/json_reader.h"
#include "storage/scene/scene_wedges.h"
#include "storage/tunnel/tunnel_files.h"

namespace rockface::storage {

namespace {

using nlohmann::json;

tunnel::DesignProfile read_shape(const Reader& r, const json& v, const std::string& p,
                                 std::string& source) {
  const std::string shape = r.string(r.require(v, p, "shape"), p + ".shape");
  source = shape;
  auto num = [&](const char* key) { return r.positive(r.require(v, p, key), p + "." + key); };
  auto any = [&](const char* key, double fallback) {
    const json* x = r.optional(v, p, key);
    return x ? r.number(*x, p + "." + key) : fallback;
  };
  if (shape == "circle") r.only_fields(v, p, {"shape", "radius", "centre_v"});
  if (shape == "rectangle") r.only_fields(v, p, {"shape", "width", "height", "floor_v"});
  if (shape == "horseshoe")
    r.only_fields(v, p, {"shape", "crown_radius", "springline_v", "wall_radius", "invert_v"});
  try {
    if (shape == "circle") return tunnel::circle_profile(num("radius"), any("centre_v", 0));
    if (shape == "rectangle")
      return tunnel::rectangle_profile(num("width"), num("height"), any("floor_v", 0));
    if (shape == "horseshoe")
      return tunnel::horseshoe_profile(num("crown_radius"), any("springline_v", 0),
                                       num("wall_radius"),
                                       r.number(r.require(v, p, "invert_v"), p + ".invert_v"));
  } catch (const InputError& e) {
    r.fail(p, e.what());
  }
  r.fail(p + ".shape", "\"" + shape + "\" is not circle, rectangle or horseshoe");
}

analysis::SceneWedgeSupportPlaces read_places(const Reader& r, const json& v,
                                              const std::string& p) {
  analysis::SceneWedgeSupportPlaces on{false, false, false, false};
  r.array(v, p);
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string s = r.string(v[i], Reader::index(p, i));
    if (s == "roof")
      on.roof = true;
    else if (s == "walls")
      on.walls = true;
    else if (s == "floor")
      on.floor = true;
    else if (s == "face")
      on.face = true;
    else
      r.fail(Reader::index(p, i), "\"" + s + "\" is not roof, walls, floor or face");
  }
  return on;
}

}  // namespace

analysis::SceneWedges read_scene_wedges(const Reader& r, const json& w,
                                        const std::string& scene_path) {
  const std::string p = "wedges";
  if (!w.is_object()) r.fail(p, "must be an object");
  static const char* known[] = {"sets",         "profile",   "axis", "chainage", "origin",
                                "trace_length", "perimeter", "face", "support"};
  for (const auto& [key, value] : w.items()) {
    (void)value;
    bool ok = false;
    for (const char* k : known) ok = ok || key == k;
    if (!ok) r.fail(p + "." + key, "unknown field (see docs/scene-extensions.md, \"wedges\")");
  }
  analysis::SceneWedges out;
  if (auto* s = r.optional(w, p, "sets")) {
    r.array(*s, p + ".sets");
    for (std::size_t i = 0; i < s->size(); ++i)
      out.sets.push_back(r.id((*s)[i], Reader::index(p + ".sets", i)));
  }
  if (auto* v = r.optional(w, p, "profile")) {
    const std::string pp = p + ".profile";
    if (v->is_string() && v->get<std::string>() == "tunnel") {
      out.profile_source = "tunnel";
    } else if (v->is_string()) {
      const std::filesystem::path f(v->get<std::string>());
      out.profile = read_profile_file(
          f.is_absolute() ? f : std::filesystem::path(scene_path).parent_path() / f);
      out.profile_source = v->get<std::string>();
    } else if (v->is_object() && v->contains("shape")) {
      out.profile = read_shape(r, *v, pp, out.profile_source);
    } else if (v->is_object()) {
      out.profile = parse_profile_json(v->dump(), r.where(pp));
      out.profile_source = "scene";
    } else {
      r.fail(pp, "must be \"tunnel\", a profile file's name, a shape object or a profile object");
    }
  }
  if (auto* a = r.optional(w, p, "axis")) {
    const std::string ap = p + ".axis";
    r.only_fields(*a, ap, {"trend", "plunge"});
    out.trend = r.number_in(r.require(*a, ap, "trend"), ap + ".trend", 0, 360);
    out.plunge = r.number_in(r.require(*a, ap, "plunge"), ap + ".plunge", -89, 89);
  }
  if (auto* c = r.optional(w, p, "chainage")) out.chainage = r.number(*c, p + ".chainage");
  if (auto* o = r.optional(w, p, "origin")) {
    out.origin = r.vec3(*o, p + ".origin");
    // Issue 41: an origin of 1e308 gave wedges of no size ("lifts", FoS 0)
    // and null coordinates in the wedges' JSON.
    if (!tunnel::within_survey_ranges(*out.origin))
      r.fail(p + ".origin", tunnel::survey_ranges_refusal());
  }
  if (auto* t = r.optional(w, p, "trace_length"))
    out.trace_length = r.positive(*t, p + ".trace_length");
  if (auto* b = r.optional(w, p, "perimeter")) out.perimeter = r.boolean(*b, p + ".perimeter");
  if (auto* b = r.optional(w, p, "face")) out.face = r.boolean(*b, p + ".face");
  if (!out.perimeter && !out.face)
    r.fail(p + ".face", "perimeter and face both false: nothing to look for");
  if (auto* s = r.optional(w, p, "support")) {
    const std::string sp = p + ".support";
    r.only_fields(*s, sp, {"bolts", "shotcrete"});
    if (auto* b = r.optional(*s, sp, "bolts")) {
      const std::string bp = sp + ".bolts";
      r.only_fields(*b, bp, {"length", "spacing", "capacity", "bond_strength", "on"});
      analysis::SceneWedgeBolts bolts;
      auto in_range = [&](const json& v, const char* key, const tunnel::SupportRange& range,
                          const char* what) {
        const double d = r.number(v, bp + "." + key);
        if (!range.contains(d)) r.fail(bp + "." + key, tunnel::outside_range_text(d, range, what));
        return d;
      };
      bolts.length = in_range(r.require(*b, bp, "length"), "length", tunnel::kBoltLengthRange,
                              "a bolt's length");
      bolts.spacing = in_range(r.require(*b, bp, "spacing"), "spacing", tunnel::kBoltSpacingRange,
                               "a bolt pattern's spacing");
      bolts.capacity = in_range(r.require(*b, bp, "capacity"), "capacity",
                                tunnel::kBoltCapacityRange, "a bolt's capacity");
      if (auto* x = r.optional(*b, bp, "bond_strength"))
        bolts.bond_strength =
            in_range(*x, "bond_strength", tunnel::kBoltBondRange, "a bolt's bond strength");
      if (auto* x = r.optional(*b, bp, "on")) bolts.on = read_places(r, *x, bp + ".on");
      out.bolts = bolts;
    }
    if (auto* c = r.optional(*s, sp, "shotcrete")) {
      const std::string cp = sp + ".shotcrete";
      r.only_fields(*c, cp, {"thickness", "shear_strength", "on"});
      analysis::SceneWedgeShotcrete sc;
      sc.thickness = r.number_in(r.require(*c, cp, "thickness"), cp + ".thickness", 1e-3, 2);
      sc.shear_strength = r.number(r.require(*c, cp, "shear_strength"), cp + ".shear_strength");
      if (!tunnel::kShotcreteShearRange.contains(sc.shear_strength))
        r.fail(cp + ".shear_strength",
               tunnel::outside_range_text(sc.shear_strength, tunnel::kShotcreteShearRange,
                                          "shotcrete's shear strength"));
      if (auto* x = r.optional(*c, cp, "on")) sc.on = read_places(r, *x, cp + ".on");
      out.shotcrete = sc;
    }
  }
  return out;
}

}  // namespace rockface::storage
