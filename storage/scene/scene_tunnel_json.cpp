// The scene's `tunnel` section. The alignment and the profile are the
// tunnel's own files (storage/tunnel/tunnel_files.h), named relative to the scene,
// or written inline (the alignment as station objects, the profile as the
// profile file's JSON object).
#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "storage/json_reader.h"
#include "storage/scene/scene_tunnel.h"
#include "storage/tunnel/tunnel_files.h"

namespace rockface::storage {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

fs::path beside(const std::string& scene_path, const std::string& name) {
  const fs::path p(name);
  return p.is_absolute() ? p : fs::path(scene_path).parent_path() / p;
}

AlignmentTable read_alignment(const Reader& r, const json& v, const std::string& scene_path) {
  const std::string p = "tunnel.alignment";
  if (v.is_string()) return read_alignment_csv(beside(scene_path, v.get<std::string>()));
  if (!v.is_object())
    r.fail(p, "must be the alignment CSV's file name or an object with \"stations\"");
  r.only_fields(v, p, {"stations"});
  const json& st = r.array(r.require(v, p, "stations"), p + ".stations");
  AlignmentTable table;
  table.source = r.where(p);
  bool any_radius = false;
  for (std::size_t i = 0; i < st.size(); ++i) {
    const std::string sp = Reader::index(p + ".stations", i);
    tunnel::AlignmentStation s;
    r.only_fields(st[i], sp, {"chainage", "easting", "northing", "elevation", "radius"});
    s.chainage = r.number(r.require(st[i], sp, "chainage"), sp + ".chainage");
    s.survey = {r.number(r.require(st[i], sp, "easting"), sp + ".easting"),
                r.number(r.require(st[i], sp, "northing"), sp + ".northing"),
                r.number(r.require(st[i], sp, "elevation"), sp + ".elevation")};
    double radius = 0;
    if (auto* rad = r.optional(st[i], sp, "radius")) {
      radius = r.number(*rad, sp + ".radius");
      any_radius = true;
    }
    table.stations.push_back(s);
    table.radii.push_back(radius);
    table.line_of.push_back(static_cast<int>(i) + 1);
  }
  if (!table.radii.empty()) table.radii.pop_back();  // one radius per element
  table.polyline = !any_radius;
  if (table.polyline) table.radii.clear();
  return table;
}

tunnel::DesignProfile read_profile(const Reader& r, const json& v, const std::string& scene_path) {
  if (v.is_string()) return read_profile_file(beside(scene_path, v.get<std::string>()));
  if (!v.is_object())
    r.fail("tunnel.profile", "must be the profile's file name (.json or .csv) or its JSON object");
  return parse_profile_json(v.dump(), r.where("tunnel.profile"));
}

}  // namespace

SceneTunnel read_scene_tunnel(const Reader& r, const json& t, const std::string& scene_path) {
  const std::string p = "tunnel";
  if (!t.is_object()) r.fail(p, "must be an object");
  r.only_fields(
      t, p,
      {"name", "alignment", "profile", "drive", "underbreak_tolerance_m", "placement", "render"});
  SceneTunnel out;
  TunnelRecord& rec = out.record;
  if (auto* v = r.optional(t, p, "name")) rec.name = r.string(*v, p + ".name");
  const json& alignment = r.require(t, p, "alignment");
  const AlignmentTable table = read_alignment(r, alignment, scene_path);
  rec.stations = table.stations;
  rec.radii = table.radii;
  rec.polyline = table.polyline;
  rec.alignment_source = alignment.is_string() ? alignment.get<std::string>() : "scene";
  const json& profile = r.require(t, p, "profile");
  rec.profile = read_profile(r, profile, scene_path);
  rec.profile_source = profile.is_string() ? profile.get<std::string>() : "scene";
  if (auto* v = r.optional(t, p, "drive"))
    rec.drive = tunnel::drive_of(r.string(*v, p + ".drive"), r.where(p + ".drive"));
  if (auto* v = r.optional(t, p, "underbreak_tolerance_m"))
    rec.underbreak_tolerance_m = r.non_negative(*v, p + ".underbreak_tolerance_m");
  if (auto* v = r.optional(t, p, "placement")) {
    const std::string pp = p + ".placement";
    r.only_fields(*v, pp, {"chainage", "offset", "height"});
    SceneTunnelPlacement placement;
    placement.chainage = r.number(r.require(*v, pp, "chainage"), pp + ".chainage");
    if (auto* o = r.optional(*v, pp, "offset")) placement.offset = r.number(*o, pp + ".offset");
    if (auto* h = r.optional(*v, pp, "height")) placement.height = r.number(*h, pp + ".height");
    out.placement = placement;
  }
  if (auto* v = r.optional(t, p, "render")) {
    const std::string rp = p + ".render";
    r.only_fields(
        *v, rp,
        {"from_chainage", "face_chainage", "section_m", "facet_m", "face_relief_m", "breaks"});
    SceneTunnelRender render;
    render.from_chainage = r.number(r.require(*v, rp, "from_chainage"), rp + ".from_chainage");
    render.face_chainage = r.number(r.require(*v, rp, "face_chainage"), rp + ".face_chainage");
    if (render.face_chainage == render.from_chainage)
      r.fail(rp + ".face_chainage", "must differ from from_chainage");
    if (auto* s = r.optional(*v, rp, "section_m"))
      render.section_m = r.number_in(*s, rp + ".section_m", 0.01, 5);
    if (auto* s = r.optional(*v, rp, "facet_m"))
      render.facet_m = r.number_in(*s, rp + ".facet_m", 0.01, 5);
    if (auto* f = r.optional(*v, rp, "face_relief_m"))
      render.face_relief_m = r.number_in(*f, rp + ".face_relief_m", 0, 2);
    if (auto* bs = r.optional(*v, rp, "breaks")) {
      r.array(*bs, rp + ".breaks");
      for (std::size_t i = 0; i < bs->size(); ++i) {
        const std::string bp = Reader::index(rp + ".breaks", i);
        const json& b = (*bs)[i];
        r.only_fields(b, bp, {"chainage", "s", "depth_m"});
        SceneTunnelBreak br;
        const json& ch = r.require(b, bp, "chainage");
        const json& s = r.require(b, bp, "s");
        if (!ch.is_array() || ch.size() != 2) r.fail(bp + ".chainage", "must be [from, to]");
        if (!s.is_array() || s.size() != 2) r.fail(bp + ".s", "must be [from, to]");
        br.chainage_from = r.number(ch[0], bp + ".chainage[0]");
        br.chainage_to = r.number(ch[1], bp + ".chainage[1]");
        br.s_from = r.non_negative(s[0], bp + ".s[0]");
        br.s_to = r.non_negative(s[1], bp + ".s[1]");
        if (!(br.chainage_to > br.chainage_from)) r.fail(bp + ".chainage", "must ascend");
        if (!(br.s_to > br.s_from)) r.fail(bp + ".s", "must ascend");
        br.depth_m = r.number_in(r.require(b, bp, "depth_m"), bp + ".depth_m", -2, 2);
        render.breaks.push_back(br);
      }
    }
    out.render = render;
  }
  // The alignment must build (ordering, element lengths, radii): refused
  // here, naming the scene, rather than at the first use. Built relative to
  // the first station, as the alignment file's own check builds it: for a
  // file that is the build kept then (built_alignment.h), not another.
  try {
    (void)rec.alignment(rec.stations.empty() ? Eigen::Vector3d::Zero()
                                             : Eigen::Vector3d(rec.stations.front().survey));
  } catch (const InputError& e) {
    r.fail(p + ".alignment", e.what());
  }
  return out;
}

}  // namespace rockface::storage
