// Parser of the scene file (SCENE.md). Every rejection names the file and the
// field path, so one line on stderr tells the geologist what to fix. The
// reader takes the JSON's shape (types, required fields, no unknown field in
// any object); what the values must be, the analysis input's checker says
// (core/analysis/analysis_input_check.h), as it does for the tablet's input.
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/analysis/analysis_input_check.h"
#include "core/common/error.h"
#include "core/common/preset.h"
#include "core/tunnel/survey_ranges.h"
#include "storage/json_reader.h"
#include "storage/scene/picks_json.h"
#include "storage/scene/rockmass_form_json.h"
#include "storage/scene/scene.h"
#include "storage/scene/scene_effects_json.h"
#include "storage/scene/scene_lighting_json.h"
#include "storage/scene/scene_tunnel.h"
#include "storage/scene/scene_wedges.h"

namespace rockface::storage {

namespace {

using nlohmann::json;

void read_orientation(const Reader& r, const json& o, const std::string& path, double& dip,
                      double& dipdir) {
  dip = r.number(r.require(o, path, "dip"), Reader::join(path, "dip"));
  dipdir = r.number(r.require(o, path, "dipdir"), Reader::join(path, "dipdir"));
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
    // "set": the joint set a project's joint is in (the scene export writes it).
    r.only_fields(j, path, {"id", "dip", "dipdir", "point", "friction", "cohesion", "set"});
    analysis::SceneJoint joint;
    joint.id = r.id(r.require(j, path, "id"), path + ".id");
    read_orientation(r, j, path, joint.dip, joint.dipdir);
    if (auto* p = r.optional(j, path, "point")) joint.point = r.vec3(*p, path + ".point");
    if (auto* f = r.optional(j, path, "friction"))
      joint.friction = r.number(*f, path + ".friction");
    if (auto* c = r.optional(j, path, "cohesion"))
      joint.cohesion = r.number(*c, path + ".cohesion");
    if (auto* s = r.optional(j, path, "set")) r.string(*s, path + ".set");
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
    r.only_fields(f, path, {"id", "dip", "dipdir", "point", "rock_side", "group"});
    analysis::SceneFreeFace face;
    face.id = r.id(r.require(f, path, "id"), path + ".id");
    read_orientation(r, f, path, face.dip, face.dipdir);
    if (auto* p = r.optional(f, path, "point")) face.point = r.vec3(*p, path + ".point");
    face.rock_side =
        analysis::rock_side_code(r.string(r.require(f, path, "rock_side"), path + ".rock_side"),
                                 r.where(path + ".rock_side"));
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
    r.only_fields(b, path, {"id", "halfspaces", "vertices", "faces"});
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
        r.only_fields(fs[k], fpath, {"plane", "loop"});
        analysis::SceneBlockFace face;
        face.plane = r.id(r.require(fs[k], fpath, "plane"), fpath + ".plane");
        const json& loop = r.array(r.require(fs[k], fpath, "loop"), fpath + ".loop");
        for (size_t m = 0; m < loop.size(); ++m)
          face.loop.push_back(r.integer(loop[m], Reader::index(fpath + ".loop", m)));
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

std::vector<analysis::ScenePatch> read_patches(const Reader& r, const json& doc) {
  std::vector<analysis::ScenePatch> patches;
  const json* surf = r.optional(doc, "", "surface");
  if (!surf) return patches;
  r.only_fields(*surf, "surface", {"patches"});
  const json* ps = r.optional(*surf, "surface", "patches");
  if (!ps) return patches;
  r.array(*ps, "surface.patches");
  for (size_t i = 0; i < ps->size(); ++i) {
    const std::string path = Reader::index("surface.patches", i);
    r.only_fields((*ps)[i], path, {"id", "polygon"});
    analysis::ScenePatch patch;
    patch.id = r.id(r.require((*ps)[i], path, "id"), path + ".id");
    patch.polygon = read_points(r, r.require((*ps)[i], path, "polygon"), path + ".polygon");
    patches.push_back(std::move(patch));
  }
  return patches;
}

std::vector<analysis::SceneTrace> read_traces(const Reader& r, const json& doc) {
  std::vector<analysis::SceneTrace> traces;
  const json* ts = r.optional(doc, "", "traces");
  if (!ts) return traces;
  r.array(*ts, "traces");
  for (size_t i = 0; i < ts->size(); ++i) {
    const std::string path = Reader::index("traces", i);
    // "pieces": the stored traces a project's joined trace is made of (the
    // scene export writes them; docs/scene-extensions.md).
    r.only_fields((*ts)[i], path, {"id", "joint", "points", "pieces"});
    analysis::SceneTrace t;
    t.id = r.id(r.require((*ts)[i], path, "id"), path + ".id");
    if (auto* j = r.optional((*ts)[i], path, "joint")) t.joint = r.id(*j, path + ".joint");
    t.points = read_points(r, r.require((*ts)[i], path, "points"), path + ".points");
    if (auto* ps = r.optional((*ts)[i], path, "pieces")) {
      r.array(*ps, path + ".pieces");
      for (size_t k = 0; k < ps->size(); ++k) r.id((*ps)[k], Reader::index(path + ".pieces", k));
    }
    traces.push_back(std::move(t));
  }
  return traces;
}

// analysis.dynamics: every field read, unknown ones refused by name.
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
  if (auto* x = r.optional(v, p, "duration_s")) d.duration_s = r.number(*x, p + ".duration_s");
  if (auto* x = r.optional(v, p, "sample_s")) d.sample_s = r.number(*x, p + ".sample_s");
  if (auto* x = r.optional(v, p, "abs_tol")) d.abs_tol = r.number(*x, p + ".abs_tol");
  if (auto* x = r.optional(v, p, "rel_tol")) d.rel_tol = r.number(*x, p + ".rel_tol");
  if (auto* x = r.optional(v, p, "max_step_s")) d.max_step_s = r.number(*x, p + ".max_step_s");
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
      if (auto* x = r.optional(*f, fp, "dip")) floor.dip = r.number(*x, fp + ".dip");
      if (auto* x = r.optional(*f, fp, "dipdir")) {
        floor.dipdir = r.number(*x, fp + ".dipdir");
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
  r.only_fields(
      *an, p,
      {"pyramids", "blocks", "rotation", "remote_axis", "stability", "preset",
       "orientation_uncertainty_deg", "reference_mass", "snap_tolerance", "survey_precision_m",
       "contact_density", "continuation_step", "max_steps", "lambda_max", "dynamics"});
  if (auto* v = r.optional(*an, p, "pyramids")) a.pyramids = r.boolean(*v, p + ".pyramids");
  if (auto* v = r.optional(*an, p, "blocks")) a.blocks = r.boolean(*v, p + ".blocks");
  if (auto* v = r.optional(*an, p, "rotation")) a.rotation = r.boolean(*v, p + ".rotation");
  // remote_axis: an object, or true for the defaults; false or absent: off.
  if (auto* v = r.optional(*an, p, "remote_axis"); v && !(v->is_boolean() && !v->get<bool>())) {
    analysis::SceneRemoteAxis ra;
    if (!v->is_boolean()) {
      r.only_fields(*v, p + ".remote_axis", {"starts", "seed"});
      if (auto* s = r.optional(*v, p + ".remote_axis", "starts"))
        ra.starts = r.integer(*s, p + ".remote_axis.starts");
      if (auto* s = r.optional(*v, p + ".remote_axis", "seed")) {
        const int seed = r.integer(*s, p + ".remote_axis.seed");
        if (seed < 0) r.fail(p + ".remote_axis.seed", "must not be negative");
        ra.seed = static_cast<unsigned>(seed);
      }
    }
    a.remote_axis = ra;
  }
  if (auto* v = r.optional(*an, p, "stability")) a.stability = r.string(*v, p + ".stability");
  if (auto* v = r.optional(*an, p, "preset")) {
    a.preset = parse_preset(r.string(*v, p + ".preset"), r.where(p + ".preset"));
  }
  if (auto* v = r.optional(*an, p, "orientation_uncertainty_deg"))
    a.orientation_uncertainty_deg = r.number(*v, p + ".orientation_uncertainty_deg");
  if (auto* v = r.optional(*an, p, "reference_mass"))
    a.reference_mass = r.number(*v, p + ".reference_mass");
  if (auto* v = r.optional(*an, p, "snap_tolerance"))
    a.snap_tolerance = r.number(*v, p + ".snap_tolerance");
  if (auto* v = r.optional(*an, p, "survey_precision_m"))
    a.survey_precision_m = r.number(*v, p + ".survey_precision_m");
  if (auto* v = r.optional(*an, p, "contact_density"))
    a.contact_density = r.integer(*v, p + ".contact_density");
  if (auto* v = r.optional(*an, p, "continuation_step"))
    a.continuation_step = r.number(*v, p + ".continuation_step");
  if (auto* v = r.optional(*an, p, "max_steps")) a.max_steps = r.integer(*v, p + ".max_steps");
  if (auto* v = r.optional(*an, p, "lambda_max")) a.lambda_max = r.number(*v, p + ".lambda_max");
  if (auto* v = r.optional(*an, p, "dynamics")) a.dynamics = read_dynamics(r, *v);
  return a;
}

SceneImaging read_imaging(const Reader& r, const json& im) {
  const std::string p = "imaging";
  r.only_fields(im, p,
                {"camera", "stations", "range_pole", "reference_line", "control_targets", "effects",
                 "texture_seed"});
  SceneImaging img;
  const json& cam = r.require(im, p, "camera");
  const std::string cp = p + ".camera";
  r.only_fields(cam, cp, {"width", "height", "fx", "fy", "cx", "cy", "distortion"});
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
    r.only_fields(st[k], sp, {"position", "look_at"});
    img.stations[k].position = r.vec3(r.require(st[k], sp, "position"), sp + ".position");
    img.stations[k].look_at = r.vec3(r.require(st[k], sp, "look_at"), sp + ".look_at");
    if ((img.stations[k].look_at - img.stations[k].position).norm() == 0)
      r.fail(sp + ".look_at", "must differ from position");
  }
  if (auto* rp = r.optional(im, p, "range_pole")) {
    const std::string pp = p + ".range_pole";
    r.only_fields(*rp, pp, {"base", "length", "target_diameter"});
    SceneRangePole pole;
    pole.base = r.vec3(r.require(*rp, pp, "base"), pp + ".base");
    if (auto* v = r.optional(*rp, pp, "length")) pole.length = r.positive(*v, pp + ".length");
    if (auto* v = r.optional(*rp, pp, "target_diameter"))
      pole.target_diameter = r.positive(*v, pp + ".target_diameter");
    img.range_pole = pole;
  }
  if (auto* rl = r.optional(im, p, "reference_line")) {
    r.only_fields(*rl, p + ".reference_line", {"from", "to"});
    img.reference_line = std::make_pair(
        r.vec3(r.require(*rl, p + ".reference_line", "from"), p + ".reference_line.from"),
        r.vec3(r.require(*rl, p + ".reference_line", "to"), p + ".reference_line.to"));
  }
  if (auto* ct = r.optional(im, p, "control_targets")) {
    const std::string cp = p + ".control_targets";
    const json& list = r.array(*ct, cp);
    if (list.size() < 3)
      r.fail(cp, "needs three or more targets (a registration by fewer is not determined), got " +
                     std::to_string(list.size()));
    for (std::size_t k = 0; k < list.size(); ++k) {
      const std::string tp = Reader::index(cp, k);
      r.only_fields(list[k], tp, {"id", "position", "diameter"});
      SceneControlTarget t;
      t.id = r.string(r.require(list[k], tp, "id"), tp + ".id");
      if (t.id.empty()) r.fail(tp + ".id", "must not be empty");
      for (const auto& other : img.control_targets)
        if (other.id == t.id) r.fail(tp + ".id", "repeats the id \"" + t.id + "\"");
      t.position = r.vec3(r.require(list[k], tp, "position"), tp + ".position");
      if (auto* v = r.optional(list[k], tp, "diameter"))
        t.diameter = r.positive(*v, tp + ".diameter");
      img.control_targets.push_back(t);
    }
  }
  if (auto* ef = r.optional(im, p, "effects")) {
    const std::string ep = p + ".effects";
    r.only_fields(*ef, ep,
                  {"distortion", "noise_sigma", "blur_px", "exposure", "flash", "lamps",
                   "vignetting", "sensor", "jpeg_quality", "wet", "shotcrete", "dust"});
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

// The parts of the scene the analysis takes, checked as the analysis input
// (the same checks as the tablet's input from a project's rows).
void check_analysis_parts(const Scene& s) {
  analysis::AnalysisInput in;
  in.source = s.source;
  in.datum = s.datum;
  in.has_datum = s.has_datum;
  in.density = s.density;
  in.gravity = s.gravity;
  in.joints = s.joints;
  in.free_faces = s.free_faces;
  in.blocks = s.blocks;
  in.patches = s.patches;
  in.traces = s.traces;
  in.analysis = s.analysis;
  in.effects = s.effects;
  analysis::check_analysis_input(in);
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
  // The top level's fields; "source": the project and visit a scene export
  // came from (docs/scene-extensions.md).
  r.only_fields(doc, "",
                {"format", "name", "datum", "rock", "gravity", "joints", "free_faces", "blocks",
                 "surface", "traces", "analysis", "effects", "imaging", "picks", "tunnel", "wedges",
                 "rockmass", "source"});
  Scene s;
  s.source = source;
  const std::string format = r.string(r.require(doc, "", "format"), "format");
  if (format != "rockface-scene/1")
    r.fail("format", "\"" + format + "\" is not \"rockface-scene/1\"");
  if (auto* v = r.optional(doc, "", "name")) s.name = r.string(*v, "name");
  if (auto* v = r.optional(doc, "", "datum")) {
    s.datum = r.vec3(*v, "datum");
    // Issue 41: a datum of 1e308 was taken and every survey coordinate
    // made from it overflowed; any survey lies within these ranges.
    if (!tunnel::within_survey_ranges(s.datum)) r.fail("datum", tunnel::survey_ranges_refusal());
    s.has_datum = true;
  }
  if (auto* rock = r.optional(doc, "", "rock")) {
    r.only_fields(*rock, "rock", {"density"});
    if (auto* d = r.optional(*rock, "rock", "density")) s.density = r.number(*d, "rock.density");
  }
  if (auto* g = r.optional(doc, "", "gravity")) s.gravity = r.vec3(*g, "gravity");
  s.joints = read_joints(r, doc);
  s.free_faces = read_free_faces(r, doc);
  s.blocks = read_blocks(r, doc);
  s.patches = read_patches(r, doc);
  s.traces = read_traces(r, doc);
  s.analysis = read_analysis(r, doc);
  if (auto* e = r.optional(doc, "", "effects")) s.effects = read_scene_effects(r, *e);
  check_analysis_parts(s);
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
