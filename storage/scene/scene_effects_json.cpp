#include "storage/scene/scene_effects_json.h"

#include <nlohmann/json.hpp>

#include "core/tunnel/survey_ranges.h"
#include "storage/json_reader.h"

namespace rockface::storage {

namespace {

using nlohmann::json;

analysis::SceneWater read_water(const Reader& r, const json& w) {
  const std::string wp = "effects.water";
  r.only_fields(w, wp, {"unit_weight", "phreatic_surface", "joints"});
  analysis::SceneWater water;
  if (auto* u = r.optional(w, wp, "unit_weight"))
    water.unit_weight = r.number(*u, wp + ".unit_weight");
  const std::string pp = wp + ".phreatic_surface";
  const json& ps = r.require(w, wp, "phreatic_surface");
  r.only_fields(ps, pp, {"point", "dip", "dipdir"});
  water.phreatic_point = r.vec3(r.require(ps, pp, "point"), pp + ".point");
  // Issue 41: a water table through a point 1e308 away put every wedge
  // under (or out of) water and read "stable".
  if (!tunnel::within_survey_ranges(water.phreatic_point))
    r.fail(pp + ".point", tunnel::survey_ranges_refusal());
  water.phreatic_dip = r.number(r.require(ps, pp, "dip"), pp + ".dip");
  water.phreatic_dipdir = r.number(r.require(ps, pp, "dipdir"), pp + ".dipdir");
  if (water.phreatic_dipdir == 360) water.phreatic_dipdir = 0;  // one direction
  if (auto* js = r.optional(w, wp, "joints")) {
    r.array(*js, wp + ".joints");
    for (size_t k = 0; k < js->size(); ++k)
      water.joints.push_back(r.id((*js)[k], Reader::index(wp + ".joints", k)));
  }
  return water;
}

analysis::SceneJointLaw read_joint_law(const Reader& r, const json& jl) {
  const std::string lp = "effects.joint_law";
  r.only_fields(jl, lp,
                {"model", "jrc", "jcs", "phi_b", "normal_stiffness", "poisson_ratio", "phi_r",
                 "lab_length", "field_length", "dilation"});
  analysis::SceneJointLaw law;
  if (auto* m = r.optional(jl, lp, "model")) law.model = r.string(*m, lp + ".model");
  if (auto* v = r.optional(jl, lp, "jrc")) law.jrc = r.number(*v, lp + ".jrc");
  if (auto* v = r.optional(jl, lp, "jcs")) law.jcs = r.number(*v, lp + ".jcs");
  if (auto* v = r.optional(jl, lp, "phi_b")) law.phi_b = r.number(*v, lp + ".phi_b");
  if (auto* v = r.optional(jl, lp, "normal_stiffness"))
    law.normal_stiffness = r.number(*v, lp + ".normal_stiffness");
  if (auto* v = r.optional(jl, lp, "poisson_ratio"))
    law.poisson_ratio = r.number(*v, lp + ".poisson_ratio");
  if (auto* v = r.optional(jl, lp, "phi_r")) law.phi_r = r.number(*v, lp + ".phi_r");
  if (auto* v = r.optional(jl, lp, "lab_length")) law.lab_length = r.number(*v, lp + ".lab_length");
  if (auto* v = r.optional(jl, lp, "field_length"))
    law.field_length = r.number(*v, lp + ".field_length");
  if (auto* v = r.optional(jl, lp, "dilation")) law.dilation = r.boolean(*v, lp + ".dilation");
  return law;
}

}  // namespace

analysis::SceneEffects read_scene_effects(const Reader& r, const json& ef) {
  const std::string p = "effects";
  if (!ef.is_object()) r.fail(p, "must be an object");
  if (ef.contains("dynamics"))
    r.fail(p + ".dynamics", "the motion after failure is asked for in analysis.dynamics");
  // "gravity" is listed and always simulated: SCENE.md's effects name it.
  r.only_fields(ef, p,
                {"gravity", "water", "seismic", "insitu_stress", "forces", "bolts", "joint_law"});
  analysis::SceneEffects e;
  if (auto* w = r.optional(ef, p, "water")) e.water = read_water(r, *w);
  if (auto* s = r.optional(ef, p, "seismic")) {
    r.only_fields(*s, p + ".seismic", {"acceleration"});
    e.seismic = r.vec3(r.require(*s, p + ".seismic", "acceleration"), p + ".seismic.acceleration");
  }
  if (auto* s = r.optional(ef, p, "insitu_stress")) {
    r.only_fields(*s, p + ".insitu_stress", {"tensor"});
    const std::string sp = p + ".insitu_stress.tensor";
    const json& t = r.require(*s, p + ".insitu_stress", "tensor");
    if (!t.is_array() || t.size() != 3) r.fail(sp, "must be a 3x3 array");
    Eigen::Matrix3d m;
    for (int i = 0; i < 3; ++i) m.row(i) = r.vec3(t[i], Reader::index(sp, i)).transpose();
    e.insitu_stress = m;
  }
  if (auto* fs = r.optional(ef, p, "forces")) {
    r.array(*fs, p + ".forces");
    for (size_t k = 0; k < fs->size(); ++k) {
      const std::string fp = Reader::index(p + ".forces", k);
      r.only_fields((*fs)[k], fp, {"vector", "point", "frame"});
      analysis::SceneForce f;
      f.vector = r.vec3(r.require((*fs)[k], fp, "vector"), fp + ".vector");
      f.point = r.vec3(r.require((*fs)[k], fp, "point"), fp + ".point");
      if (auto* fr = r.optional((*fs)[k], fp, "frame")) f.frame = r.string(*fr, fp + ".frame");
      e.forces.push_back(f);
    }
  }
  if (auto* bs = r.optional(ef, p, "bolts")) {
    r.array(*bs, p + ".bolts");
    for (size_t k = 0; k < bs->size(); ++k) {
      const std::string bp = Reader::index(p + ".bolts", k);
      r.only_fields((*bs)[k], bp, {"point", "trend", "plunge", "force"});
      analysis::SceneBolt b;
      b.point = r.vec3(r.require((*bs)[k], bp, "point"), bp + ".point");
      b.trend = r.number(r.require((*bs)[k], bp, "trend"), bp + ".trend");
      b.plunge = r.number(r.require((*bs)[k], bp, "plunge"), bp + ".plunge");
      b.force = r.number(r.require((*bs)[k], bp, "force"), bp + ".force");
      e.bolts.push_back(b);
    }
  }
  if (auto* jl = r.optional(ef, p, "joint_law")) e.joint_law = read_joint_law(r, *jl);
  return e;
}

}  // namespace rockface::storage
