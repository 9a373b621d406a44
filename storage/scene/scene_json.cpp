// Parser of the scene file (SCENE.md). Every rejection names the file and the
// field path, so one line on stderr tells the geologist what to fix.
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/common/preset.h"
#include "storage/json_reader.h"
#include "storage/scene/picks_json.h"
#include "storage/scene/rockmass_form_json.h"
#include "storage/scene/scene.h"
#include "storage/scene/scene_lighting_json.h"
#include "storage/scene/scene_tunnel.h"
#include "storage/scene/scene_wedges.h"

namespace rockface::storage {

namespace {

using nlohmann::json;

void read_orientation(const Reader& r, const json& o, const std::string& path, double& dip,
                      double& dipdir) {
  dip = r.number_in(r.require(o, path, "dip"), Reader::join(path, "dip"), 0, 90);
  dipdir = r.number_in(r.require(o, path, "dipdir"), Reader::join(path, "dipdir"), 0, 360);
  if (dipdir == 360) dipdir = 0;  // 360 and 0 are one direction
}

std::vector<analysis::SceneJoint> read_joints(const Reader& r, const json& doc) {
  std::vector<analysis::SceneJoint> joints;
  const json* arr = r.optional(doc, "", "joints");
  if (!arr) return joints;
  r.array(*arr, "joints");
  for (size_t i = 0; i < arr->size(); ++i) {
    const json& j = (*arr)[i];
    const std::string path = Reader::index("joints", i);
    analysis::SceneJoint joint;
    joint.id = r.id(r.require(j, path, "id"), path + ".id");
    read_orientation(r, j, path, joint.dip, joint.dipdir);
    if (auto* p = r.optional(j, path, "point")) joint.point = r.vec3(*p, path + ".point");
    if (auto* f = r.optional(j, path, "friction"))
      joint.friction = r.number_in(*f, path + ".friction", 0, 90, true);
    if (auto* c = r.optional(j, path, "cohesion"))
      joint.cohesion = r.non_negative(*c, path + ".cohesion");
    joints.push_back(std::move(joint));
  }
  return joints;
}

std::vector<analysis::SceneFreeFace> read_free_faces(const Reader& r, const json& doc) {
  std::vector<analysis::SceneFreeFace> faces;
  const json* arr = r.optional(doc, "", "free_faces");
  if (!arr) return faces;
  r.array(*arr, "free_faces");
  for (size_t i = 0; i < arr->size(); ++i) {
    const json& f = (*arr)[i];
    const std::string path = Reader::index("free_faces", i);
    analysis::SceneFreeFace face;
    face.id = r.id(r.require(f, path, "id"), path + ".id");
    read_orientation(r, f, path, face.dip, face.dipdir);
    if (auto* p = r.optional(f, path, "point")) face.point = r.vec3(*p, path + ".point");
    const std::string side = r.string(r.require(f, path, "rock_side"), path + ".rock_side");
    if (side == "upper")
      face.rock_side = 0;
    else if (side == "lower")
      face.rock_side = 1;
    else
      r.fail(path + ".rock_side", "\"" + side + "\" is neither \"upper\" nor \"lower\"");
    if (auto* g = r.optional(f, path, "group")) face.group = r.id(*g, path + ".group");
    faces.push_back(std::move(face));
  }
  return faces;
}

int halfspace_code(const Reader& r, const json& v, const std::string& path) {
  if (v.is_string()) {
    const std::string s = v.get<std::string>();
    if (s == "upper") return 0;
    if (s == "lower") return 1;
  } else if (v.is_number_integer()) {
    const int c = v.get<int>();
    if (c == 0 || c == 1) return c;
  }
  r.fail(path, v.dump() + " is neither \"upper\" nor \"lower\"");
}

std::vector<analysis::SceneBlock> read_blocks(const Reader& r, const json& doc) {
  std::vector<analysis::SceneBlock> blocks;
  const json* arr = r.optional(doc, "", "blocks");
  if (!arr) return blocks;
  r.array(*arr, "blocks");
  for (size_t i = 0; i < arr->size(); ++i) {
    const json& b = (*arr)[i];
    const std::string path = Reader::index("blocks", i);
    analysis::SceneBlock block;
    block.id = r.id(r.require(b, path, "id"), path + ".id");
    const json* hs = r.optional(b, path, "halfspaces");
    const json* vs = r.optional(b, path, "vertices");
    if ((hs != nullptr) == (vs != nullptr))
      r.fail(path, "give either \"halfspaces\" or \"vertices\" + \"faces\"");
    if (hs) {
      if (!hs->is_object() || hs->empty())
        r.fail(path + ".halfspaces", "must be a non-empty object of plane id -> side");
      for (auto it = hs->begin(); it != hs->end(); ++it)
        block.halfspaces[it.key()] =
            halfspace_code(r, it.value(), path + ".halfspaces." + it.key());
    } else {
      r.array(*vs, path + ".vertices");
      for (size_t k = 0; k < vs->size(); ++k)
        block.vertices.push_back(r.vec3((*vs)[k], Reader::index(path + ".vertices", k)));
      const json& fs = r.array(r.require(b, path, "faces"), path + ".faces");
      for (size_t k = 0; k < fs.size(); ++k) {
        const std::string fpath = Reader::index(path + ".faces", k);
        analysis::SceneBlockFace face;
        face.plane = r.id(r.require(fs[k], fpath, "plane"), fpath + ".plane");
        const json& loop = r.array(r.require(fs[k], fpath, "loop"), fpath + ".loop");
        if (loop.size() < 3) r.fail(fpath + ".loop", "needs at least 3 vertices");
        for (size_t m = 0; m < loop.size(); ++m) {
          const int v = r.integer(loop[m], Reader::index(fpath + ".loop", m));
          if (v < 0 || v >= static_cast<int>(block.vertices.size()))
            r.fail(Reader::index(fpath + ".loop", m),
                   "vertex index " + std::to_string(v) + " is out of range (block has " +
                       std::to_string(block.vertices.size()) + " vertices)");
          face.loop.push_back(v);
        }
        block.faces.push_back(std::move(face));
      }
    }
    blocks.push_back(std::move(block));
  }
  return blocks;
}

std::vector<Eigen::Vector3d> read_points(const Reader& r, const json& v, const std::string& path) {
  r.array(v, path);
  std::vector<Eigen::Vector3d> pts;
  for (size_t k = 0; k < v.size(); ++k) pts.push_back(r.vec3(v[k], Reader::index(path, k)));
  return pts;
}

// analysis.dynamics: every field checked, unknown ones refused by name.
analysis::SceneDynamics read_dynamics(const Reader& r, const json& v) {
  const std::string p = "analysis.dynamics";
  if (!v.is_object()) r.fail(p, "must be an object");
  static const std::set<std::string> known = {"duration_s", "sample_s", "floor",
                                              "abs_tol",    "rel_tol",  "max_step_s"};
  for (auto it = v.begin(); it != v.end(); ++it)
    if (!known.count(it.key()))
      r.fail(p + "." + it.key(),
             "unknown field (duration_s, sample_s, floor, abs_tol, rel_tol, max_step_s)");
  analysis::SceneDynamics d;
  if (auto* x = r.optional(v, p, "duration_s"))
    d.duration_s = r.number_in(*x, p + ".duration_s", 1e-3, 600);
  if (auto* x = r.optional(v, p, "sample_s")) d.sample_s = r.positive(*x, p + ".sample_s");
  if (d.duration_s / d.sample_s > 100000)
    r.fail(p + ".sample_s", "more than 100000 samples over duration_s");
  if (auto* x = r.optional(v, p, "abs_tol"))
    d.abs_tol = r.number_in(*x, p + ".abs_tol", 1e-15, 1e-2);
  if (auto* x = r.optional(v, p, "rel_tol"))
    d.rel_tol = r.number_in(*x, p + ".rel_tol", 1e-14, 1e-2);
  if (auto* x = r.optional(v, p, "max_step_s"))
    d.max_step_s = r.number_in(*x, p + ".max_step_s", 1e-6, 1);
  if (auto* f = r.optional(v, p, "floor")) {
    const std::string fp = p + ".floor";
    if (!f->is_object()) r.fail(fp, "must be an object");
    static const std::set<std::string> floor_keys = {"elevation", "point", "dip", "dipdir"};
    for (auto it = f->begin(); it != f->end(); ++it)
      if (!floor_keys.count(it.key()))
        r.fail(fp + "." + it.key(), "unknown field (elevation, or point with dip and dipdir)");
    analysis::SceneFloor floor;
    const json* elevation = r.optional(*f, fp, "elevation");
    const json* point = r.optional(*f, fp, "point");
    if ((elevation != nullptr) == (point != nullptr))
      r.fail(fp, "give either elevation (a level floor, m) or point (with dip and dipdir)");
    if (elevation) {
      floor.point = Eigen::Vector3d(0, 0, r.number(*elevation, fp + ".elevation"));
      if (r.optional(*f, fp, "dip") || r.optional(*f, fp, "dipdir"))
        r.fail(fp + ".dip", "a floor given by elevation is level: give point, dip and dipdir");
    } else {
      floor.point = r.vec3(*point, fp + ".point");
      if (auto* x = r.optional(*f, fp, "dip"))
        floor.dip = r.number_in(*x, fp + ".dip", 0, 90, true);
      if (auto* x = r.optional(*f, fp, "dipdir")) {
        floor.dipdir = r.number_in(*x, fp + ".dipdir", 0, 360);
        if (floor.dipdir == 360) floor.dipdir = 0;
      }
    }
    d.floor = floor;
  }
  return d;
}

analysis::SceneAnalysis read_analysis(const Reader& r, const json& doc) {
  analysis::SceneAnalysis a;
  const json* an = r.optional(doc, "", "analysis");
  if (!an) return a;
  const std::string p = "analysis";
  if (auto* v = r.optional(*an, p, "pyramids")) a.pyramids = r.boolean(*v, p + ".pyramids");
  if (auto* v = r.optional(*an, p, "blocks")) a.blocks = r.boolean(*v, p + ".blocks");
  if (auto* v = r.optional(*an, p, "rotation")) a.rotation = r.boolean(*v, p + ".rotation");
  // remote_axis: an object, or true for the defaults; false or absent: off.
  if (auto* v = r.optional(*an, p, "remote_axis"); v && !(v->is_boolean() && !v->get<bool>())) {
    analysis::SceneRemoteAxis ra;
    if (!v->is_boolean()) {
      if (auto* s = r.optional(*v, p + ".remote_axis", "starts")) {
        ra.starts = r.integer(*s, p + ".remote_axis.starts");
        if (*ra.starts < 1 || *ra.starts > 100000)
          r.fail(p + ".remote_axis.starts", "must be between 1 and 100000");
      }
      if (auto* s = r.optional(*v, p + ".remote_axis", "seed")) {
        const int seed = r.integer(*s, p + ".remote_axis.seed");
        if (seed < 0) r.fail(p + ".remote_axis.seed", "must not be negative");
        ra.seed = static_cast<unsigned>(seed);
      }
    }
    a.remote_axis = ra;
  }
  if (auto* v = r.optional(*an, p, "stability")) {
    a.stability = r.string(*v, p + ".stability");
    if (a.stability != "limit_equilibrium" && a.stability != "equilibrium_path" &&
        a.stability != "none")
      r.fail(p + ".stability",
             "\"" + a.stability + "\" is not limit_equilibrium, equilibrium_path or none");
  }
  if (auto* v = r.optional(*an, p, "preset")) {
    a.preset = parse_preset(r.string(*v, p + ".preset"), r.where(p + ".preset"));
  }
  if (auto* v = r.optional(*an, p, "orientation_uncertainty_deg"))
    a.orientation_uncertainty_deg = r.number_in(*v, p + ".orientation_uncertainty_deg", 0, 45);
  if (auto* v = r.optional(*an, p, "reference_mass"))
    a.reference_mass = r.positive(*v, p + ".reference_mass");
  if (auto* v = r.optional(*an, p, "snap_tolerance"))
    a.snap_tolerance = r.non_negative(*v, p + ".snap_tolerance");
  if (auto* v = r.optional(*an, p, "contact_density")) {
    a.contact_density = r.integer(*v, p + ".contact_density");
    if (*a.contact_density < 1 || *a.contact_density > 64)
      r.fail(p + ".contact_density", "must be between 1 and 64 sub-divisions per edge");
  }
  if (auto* v = r.optional(*an, p, "continuation_step"))
    a.continuation_step = r.number_in(*v, p + ".continuation_step", 1e-6, 10);
  if (auto* v = r.optional(*an, p, "max_steps")) {
    a.max_steps = r.integer(*v, p + ".max_steps");
    if (*a.max_steps < 1 || *a.max_steps > 100000)
      r.fail(p + ".max_steps", "must be between 1 and 100000");
  }
  if (auto* v = r.optional(*an, p, "lambda_max"))
    a.lambda_max = r.number_in(*v, p + ".lambda_max", 0.1, 1e6);
  if (auto* v = r.optional(*an, p, "dynamics")) a.dynamics = read_dynamics(r, *v);
  return a;
}

analysis::SceneEffects read_effects(const Reader& r, const json& doc) {
  analysis::SceneEffects e;
  const json* ef = r.optional(doc, "", "effects");
  if (!ef) return e;
  const std::string p = "effects";
  if (!ef->is_object()) r.fail(p, "must be an object");
  static const std::set<std::string> known = {"gravity", "water", "seismic",   "insitu_stress",
                                              "forces",  "bolts", "joint_law", "dynamics"};
  for (auto it = ef->begin(); it != ef->end(); ++it)
    if (!known.count(it.key())) r.fail(p + "." + it.key(), "unknown effect");
  if (ef->contains("dynamics"))
    r.fail(p + ".dynamics", "the motion after failure is asked for in analysis.dynamics");
  if (auto* w = r.optional(*ef, p, "water")) {
    const std::string wp = p + ".water";
    analysis::SceneWater water;
    if (auto* u = r.optional(*w, wp, "unit_weight"))
      water.unit_weight = r.positive(*u, wp + ".unit_weight");
    const json& ps = r.require(*w, wp, "phreatic_surface");
    water.phreatic_point =
        r.vec3(r.require(ps, wp + ".phreatic_surface", "point"), wp + ".phreatic_surface.point");
    read_orientation(r, ps, wp + ".phreatic_surface", water.phreatic_dip, water.phreatic_dipdir);
    if (auto* js = r.optional(*w, wp, "joints")) {
      r.array(*js, wp + ".joints");
      for (size_t k = 0; k < js->size(); ++k)
        water.joints.push_back(r.id((*js)[k], Reader::index(wp + ".joints", k)));
    }
    e.water = water;
  }
  if (auto* s = r.optional(*ef, p, "seismic"))
    e.seismic = r.vec3(r.require(*s, p + ".seismic", "acceleration"), p + ".seismic.acceleration");
  if (auto* s = r.optional(*ef, p, "insitu_stress")) {
    const std::string sp = p + ".insitu_stress.tensor";
    const json& t = r.require(*s, p + ".insitu_stress", "tensor");
    if (!t.is_array() || t.size() != 3) r.fail(sp, "must be a 3x3 array");
    Eigen::Matrix3d m;
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d row = r.vec3(t[i], Reader::index(sp, i));
      m.row(i) = row.transpose();
    }
    if ((m - m.transpose()).cwiseAbs().maxCoeff() > 1e-9 * std::max(1.0, m.cwiseAbs().maxCoeff()))
      r.fail(sp, "must be symmetric");
    e.insitu_stress = m;
  }
  if (auto* fs = r.optional(*ef, p, "forces")) {
    r.array(*fs, p + ".forces");
    for (size_t k = 0; k < fs->size(); ++k) {
      const std::string fp = Reader::index(p + ".forces", k);
      analysis::SceneForce f;
      f.vector = r.vec3(r.require((*fs)[k], fp, "vector"), fp + ".vector");
      f.point = r.vec3(r.require((*fs)[k], fp, "point"), fp + ".point");
      if (auto* fr = r.optional((*fs)[k], fp, "frame")) {
        f.frame = r.string(*fr, fp + ".frame");
        if (f.frame != "space" && f.frame != "block")
          r.fail(fp + ".frame", "\"" + f.frame + "\" is neither \"space\" nor \"block\"");
      }
      e.forces.push_back(f);
    }
  }
  if (auto* bs = r.optional(*ef, p, "bolts")) {
    r.array(*bs, p + ".bolts");
    for (size_t k = 0; k < bs->size(); ++k) {
      const std::string bp = Reader::index(p + ".bolts", k);
      analysis::SceneBolt b;
      b.point = r.vec3(r.require((*bs)[k], bp, "point"), bp + ".point");
      b.trend = r.number_in(r.require((*bs)[k], bp, "trend"), bp + ".trend", 0, 360);
      b.plunge = r.number_in(r.require((*bs)[k], bp, "plunge"), bp + ".plunge", -90, 90);
      b.force = r.non_negative(r.require((*bs)[k], bp, "force"), bp + ".force");
      e.bolts.push_back(b);
    }
  }
  if (auto* jl = r.optional(*ef, p, "joint_law")) {
    const std::string lp = p + ".joint_law";
    analysis::SceneJointLaw law;
    if (auto* m = r.optional(*jl, lp, "model")) {
      law.model = r.string(*m, lp + ".model");
      if (law.model != "barton_bandis" && law.model != "grasselli" && law.model != "coulomb")
        r.fail(lp + ".model", "\"" + law.model + "\" is not barton_bandis, grasselli or coulomb");
    }
    if (auto* v = r.optional(*jl, lp, "jrc")) law.jrc = r.number_in(*v, lp + ".jrc", 0, 20);
    if (auto* v = r.optional(*jl, lp, "jcs")) law.jcs = r.positive(*v, lp + ".jcs");
    if (auto* v = r.optional(*jl, lp, "phi_b"))
      law.phi_b = r.number_in(*v, lp + ".phi_b", 0, 90, true);
    if (auto* v = r.optional(*jl, lp, "normal_stiffness"))
      law.normal_stiffness = r.positive(*v, lp + ".normal_stiffness");
    if (auto* v = r.optional(*jl, lp, "poisson_ratio"))
      law.poisson_ratio = r.number_in(*v, lp + ".poisson_ratio", -0.99, 0.49);
    if (auto* v = r.optional(*jl, lp, "phi_r"))
      law.phi_r = r.number_in(*v, lp + ".phi_r", 0, 90, true);
    if (auto* v = r.optional(*jl, lp, "lab_length"))
      law.lab_length = r.positive(*v, lp + ".lab_length");
    if (auto* v = r.optional(*jl, lp, "field_length"))
      law.field_length = r.positive(*v, lp + ".field_length");
    if (auto* v = r.optional(*jl, lp, "dilation")) law.dilation = r.boolean(*v, lp + ".dilation");
    e.joint_law = law;
  }
  return e;
}

SceneImaging read_imaging(const Reader& r, const json& im) {
  const std::string p = "imaging";
  SceneImaging img;
  const json& cam = r.require(im, p, "camera");
  const std::string cp = p + ".camera";
  img.camera.width = r.integer(r.require(cam, cp, "width"), cp + ".width");
  img.camera.height = r.integer(r.require(cam, cp, "height"), cp + ".height");
  if (img.camera.width < 16 || img.camera.width > 20000)
    r.fail(cp + ".width", "must be between 16 and 20000 pixels");
  if (img.camera.height < 16 || img.camera.height > 20000)
    r.fail(cp + ".height", "must be between 16 and 20000 pixels");
  img.camera.fx = r.positive(r.require(cam, cp, "fx"), cp + ".fx");
  img.camera.fy = r.positive(r.require(cam, cp, "fy"), cp + ".fy");
  img.camera.cx = r.number(r.require(cam, cp, "cx"), cp + ".cx");
  img.camera.cy = r.number(r.require(cam, cp, "cy"), cp + ".cy");
  if (auto* d = r.optional(cam, cp, "distortion")) {
    if (!d->is_array() || d->size() != 5)
      r.fail(cp + ".distortion", "must be 5 numbers [k1, k2, p1, p2, k3]");
    for (int k = 0; k < 5; ++k)
      img.camera.distortion[k] = r.number((*d)[k], Reader::index(cp + ".distortion", k));
  }
  const json& st = r.array(r.require(im, p, "stations"), p + ".stations");
  if (st.size() < 2 || st.size() % 2 != 0)
    r.fail(p + ".stations",
           "must hold stations in pairs (left, right; then left, right of each further pair), "
           "got " +
               std::to_string(st.size()));
  img.stations.resize(st.size());
  for (size_t k = 0; k < st.size(); ++k) {
    const std::string sp = Reader::index(p + ".stations", k);
    img.stations[k].position = r.vec3(r.require(st[k], sp, "position"), sp + ".position");
    img.stations[k].look_at = r.vec3(r.require(st[k], sp, "look_at"), sp + ".look_at");
    if ((img.stations[k].look_at - img.stations[k].position).norm() == 0)
      r.fail(sp + ".look_at", "must differ from position");
  }
  if (auto* rp = r.optional(im, p, "range_pole")) {
    const std::string pp = p + ".range_pole";
    SceneRangePole pole;
    pole.base = r.vec3(r.require(*rp, pp, "base"), pp + ".base");
    if (auto* v = r.optional(*rp, pp, "length")) pole.length = r.positive(*v, pp + ".length");
    if (auto* v = r.optional(*rp, pp, "target_diameter"))
      pole.target_diameter = r.positive(*v, pp + ".target_diameter");
    img.range_pole = pole;
  }
  if (auto* rl = r.optional(im, p, "reference_line"))
    img.reference_line = std::make_pair(
        r.vec3(r.require(*rl, p + ".reference_line", "from"), p + ".reference_line.from"),
        r.vec3(r.require(*rl, p + ".reference_line", "to"), p + ".reference_line.to"));
  if (auto* ef = r.optional(im, p, "effects")) {
    const std::string ep = p + ".effects";
    if (auto* v = r.optional(*ef, ep, "distortion"))
      img.effects.distortion = r.boolean(*v, ep + ".distortion");
    if (auto* v = r.optional(*ef, ep, "noise_sigma"))
      img.effects.noise_sigma = r.non_negative(*v, ep + ".noise_sigma");
    if (auto* v = r.optional(*ef, ep, "blur_px"))
      img.effects.blur_px = r.non_negative(*v, ep + ".blur_px");
    if (auto* v = r.optional(*ef, ep, "exposure"))
      img.effects.exposure = r.positive(*v, ep + ".exposure");
    read_tunnel_lighting(r, *ef, ep, img.effects);
  }
  if (auto* v = r.optional(im, p, "texture_seed")) {
    const int seed = r.integer(*v, p + ".texture_seed");
    if (seed < 0) r.fail(p + ".texture_seed", "must not be negative");
    img.texture_seed = static_cast<unsigned>(seed);
  }
  return img;
}

// Cross-field checks: unique ids, known plane ids in blocks, traces and water.
void check_references(const Reader& r, const Scene& s) {
  std::set<std::string> planes;
  for (size_t i = 0; i < s.joints.size(); ++i)
    if (!planes.insert(s.joints[i].id).second)
      r.fail(Reader::index("joints", i) + ".id", "duplicate id \"" + s.joints[i].id + "\"");
  for (size_t i = 0; i < s.free_faces.size(); ++i)
    if (!planes.insert(s.free_faces[i].id).second)
      r.fail(Reader::index("free_faces", i) + ".id", "duplicate id \"" + s.free_faces[i].id + "\"");
  auto check_ids = [&](const auto& items, const char* what) {
    std::set<std::string> ids;
    for (size_t i = 0; i < items.size(); ++i)
      if (!ids.insert(items[i].id).second)
        r.fail(Reader::index(what, i) + ".id", "duplicate id \"" + items[i].id + "\"");
  };
  check_ids(s.blocks, "blocks");
  check_ids(s.patches, "surface.patches");
  check_ids(s.traces, "traces");
  for (size_t i = 0; i < s.blocks.size(); ++i) {
    const std::string path = Reader::index("blocks", i);
    for (const auto& [id, code] : s.blocks[i].halfspaces)
      if (!planes.count(id)) r.fail(path + ".halfspaces." + id, "unknown plane id \"" + id + "\"");
    for (size_t k = 0; k < s.blocks[i].faces.size(); ++k)
      if (!planes.count(s.blocks[i].faces[k].plane))
        r.fail(Reader::index(path + ".faces", k) + ".plane",
               "unknown plane id \"" + s.blocks[i].faces[k].plane + "\"");
  }
  for (size_t i = 0; i < s.traces.size(); ++i)
    if (s.traces[i].joint && !s.joint(*s.traces[i].joint))
      r.fail(Reader::index("traces", i) + ".joint",
             "unknown joint id \"" + *s.traces[i].joint + "\"");
  if (s.effects.water)
    for (size_t k = 0; k < s.effects.water->joints.size(); ++k)
      if (!s.joint(s.effects.water->joints[k]))
        r.fail(Reader::index("effects.water.joints", k),
               "unknown joint id \"" + s.effects.water->joints[k] + "\"");
}

}  // namespace

const analysis::SceneJoint* Scene::joint(const std::string& id) const {
  for (const auto& j : joints)
    if (j.id == id) return &j;
  return nullptr;
}

const analysis::SceneFreeFace* Scene::free_face(const std::string& id) const {
  for (const auto& f : free_faces)
    if (f.id == id) return &f;
  return nullptr;
}

int Scene::plane_index(const std::string& id) const {
  for (size_t i = 0; i < joints.size(); ++i)
    if (joints[i].id == id) return static_cast<int>(i);
  for (size_t i = 0; i < free_faces.size(); ++i)
    if (free_faces[i].id == id) return static_cast<int>(joints.size() + i);
  return -1;
}

Scene parse_scene(const std::string& text, const std::string& source) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::out_of_range&) {
    throw_number_overflow(text, source);
  } catch (const json::exception& e) {
    // nlohmann reports the byte offset; that is where the JSON breaks. Also
    // a number beyond double's range (1e309), found by tests/storage/fuzz.
    throw InputError(source, std::string("not valid JSON (") + e.what() + ")");
  }
  const Reader r(source);
  if (!doc.is_object()) r.fail("(top level)", "must be a JSON object");
  Scene s;
  s.source = source;
  const std::string format = r.string(r.require(doc, "", "format"), "format");
  if (format != "rockface-scene/1")
    r.fail("format", "\"" + format + "\" is not \"rockface-scene/1\"");
  if (auto* v = r.optional(doc, "", "name")) s.name = r.string(*v, "name");
  if (auto* v = r.optional(doc, "", "datum")) {
    s.datum = r.vec3(*v, "datum");
    s.has_datum = true;
  }
  if (auto* rock = r.optional(doc, "", "rock"))
    if (auto* d = r.optional(*rock, "rock", "density")) s.density = r.positive(*d, "rock.density");
  if (auto* g = r.optional(doc, "", "gravity")) s.gravity = r.vec3(*g, "gravity");
  s.joints = read_joints(r, doc);
  s.free_faces = read_free_faces(r, doc);
  s.blocks = read_blocks(r, doc);
  if (auto* surf = r.optional(doc, "", "surface")) {
    if (auto* ps = r.optional(*surf, "surface", "patches")) {
      r.array(*ps, "surface.patches");
      for (size_t i = 0; i < ps->size(); ++i) {
        const std::string path = Reader::index("surface.patches", i);
        analysis::ScenePatch patch;
        patch.id = r.id(r.require((*ps)[i], path, "id"), path + ".id");
        patch.polygon = read_points(r, r.require((*ps)[i], path, "polygon"), path + ".polygon");
        if (patch.polygon.size() < 3) r.fail(path + ".polygon", "needs at least 3 points");
        s.patches.push_back(std::move(patch));
      }
    }
  }
  if (auto* ts = r.optional(doc, "", "traces")) {
    r.array(*ts, "traces");
    for (size_t i = 0; i < ts->size(); ++i) {
      const std::string path = Reader::index("traces", i);
      analysis::SceneTrace t;
      t.id = r.id(r.require((*ts)[i], path, "id"), path + ".id");
      if (auto* j = r.optional((*ts)[i], path, "joint")) t.joint = r.id(*j, path + ".joint");
      // A trace with fewer than two points is kept: the trace network rejects
      // it with its own message and the rest of the map goes on.
      t.points = read_points(r, r.require((*ts)[i], path, "points"), path + ".points");
      s.traces.push_back(std::move(t));
    }
  }
  s.analysis = read_analysis(r, doc);
  s.effects = read_effects(r, doc);
  if (auto* im = r.optional(doc, "", "imaging")) s.imaging = read_imaging(r, *im);
  if (auto* p = r.optional(doc, "", "picks")) {
    s.picks = read_picks(*p, source, "picks");
    for (const auto& t : s.picks->traces)
      if (!t.joint.empty() && !s.joint(t.joint))
        r.fail(t.where + ".joint", "unknown joint id \"" + t.joint + "\"");
  }
  if (auto* t = r.optional(doc, "", "tunnel")) s.tunnel = read_scene_tunnel(r, *t, source);
  if (auto* w = r.optional(doc, "", "wedges")) {
    s.wedges = read_scene_wedges(r, *w, source);
    for (std::size_t i = 0; i < s.wedges->sets.size(); ++i)
      if (!s.joint(s.wedges->sets[i]))
        r.fail(Reader::index("wedges.sets", i), "unknown joint id \"" + s.wedges->sets[i] + "\"");
  }
  if (auto* f = r.optional(doc, "", "rockmass")) s.rockmass = read_rockmass_form(r, *f, "rockmass");
  check_references(r, s);
  return s;
}

Scene load_scene(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path, "cannot read the scene file");
  return parse_scene(text.str(), path);
}

}  // namespace rockface::storage
