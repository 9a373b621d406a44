// Parser of the picks (core/measure/picks.h, docs/scene-extensions.md).
#include "storage/scene/picks_json.h"

#include <fstream>
#include <set>
#include <sstream>

#include "core/common/error.h"
#include "storage/json_reader.h"

namespace rockface::storage {

using measure::AreaPick;
using measure::Picks;
using measure::PointPick;
using measure::TracePick;

namespace {

using nlohmann::json;

Eigen::Vector2d pixel(const Reader& r, const json& v, const std::string& path) {
  if (!v.is_array() || v.size() != 2) r.fail(path, "must be a pixel [u, v]");
  return {r.number(v[0], path + "[0]"), r.number(v[1], path + "[1]")};
}

std::vector<Eigen::Vector2d> pixels(const Reader& r, const json& v, const std::string& path) {
  r.array(v, path);
  std::vector<Eigen::Vector2d> out;
  for (std::size_t i = 0; i < v.size(); ++i) out.push_back(pixel(r, v[i], Reader::index(path, i)));
  return out;
}

std::string photo(const Reader& r, const json& o, const std::string& path) {
  const std::string p = r.string(r.require(o, path, "photo"), Reader::join(path, "photo"));
  if (p != "left" && p != "right")
    r.fail(Reader::join(path, "photo"), "\"" + p + "\" is not \"left\" or \"right\"");
  return p;
}

// The pair of an area or a point picked in `photo`.
int pair_of(const Reader& r, const json& o, const std::string& path, const std::string& photo) {
  const json* n = r.optional(o, path, "pair");
  if (!n) return 1;
  const int pair = r.integer(*n, path + ".pair");
  if (pair < 1) r.fail(path + ".pair", "pairs are counted from 1");
  if (pair > 1 && photo != "left")
    r.fail(path + ".photo", "a further pair's pick is made in its left photograph");
  return pair;
}

// A trace needs two distinct picks: one point (or one pixel tapped twice)
// is no line, let alone a plane.
template <typename V>
void require_two_distinct(const Reader& r, const std::vector<V>& v, const std::string& path) {
  if (v.size() < 2)
    r.fail(path, "a trace needs at least two picks, found " + std::to_string(v.size()));
  for (const auto& p : v)
    if (p != v.front()) return;
  r.fail(path, "all " + std::to_string(v.size()) + " picks are the same point: a one-point trace");
}

// A compass reading of a trace's joint (issue 27): dip [0, 90] and dip
// direction [0, 360] in degrees, as a Clar compass reads them.
measure::CompassReading compass(const Reader& r, const json& v, const std::string& path) {
  if (!v.is_object()) r.fail(path, "must be an object {\"dip\": .., \"dip_direction\": ..}");
  measure::CompassReading reading;
  reading.dip_deg = r.number_in(r.require(v, path, "dip"), path + ".dip", 0, 90);
  reading.dip_direction_deg =
      r.number_in(r.require(v, path, "dip_direction"), path + ".dip_direction", 0, 360);
  for (const auto& [key, value] : v.items())
    if (key != "dip" && key != "dip_direction")
      r.fail(path + "." + key, "is not a field of a compass reading (dip, dip_direction)");
  return reading;
}

}  // namespace

Picks read_picks(const json& object, const std::string& source, const std::string& base) {
  const Reader r(source);
  const std::string top = base.empty() ? "(top level)" : base;
  if (!object.is_object()) r.fail(top, "must be a JSON object");
  if (base.empty())
    r.only_fields(object, "", {"format", "traces", "areas", "points", "sets"});
  else
    r.only_fields(object, base, {"traces", "areas", "points", "sets"});
  auto at = [&](const std::string& key) { return base.empty() ? key : base + "." + key; };
  Picks picks;
  std::set<std::string> ids;
  auto unique = [&](const std::string& id, const std::string& path) {
    if (!ids.insert(id).second) r.fail(path, "id \"" + id + "\" is used twice");
  };

  if (auto* ts = r.optional(object, top, "traces")) {
    r.array(*ts, at("traces"));
    for (std::size_t i = 0; i < ts->size(); ++i) {
      const json& t = (*ts)[i];
      const std::string path = Reader::index(at("traces"), i);
      r.only_fields(t, path,
                    {"id", "joint", "origin", "photo", "pair", "pixels", "points", "ends", "cost",
                     "compass"});
      TracePick pick;
      pick.where = path;
      pick.id = r.id(r.require(t, path, "id"), path + ".id");
      unique(pick.id, path + ".id");
      if (auto* j = r.optional(t, path, "joint")) pick.joint = r.id(*j, path + ".joint");
      if (auto* o = r.optional(t, path, "origin")) {
        pick.origin = r.string(*o, path + ".origin");
        if (pick.origin != "hand" && pick.origin != "proposed" && pick.origin != "corrected")
          r.fail(path + ".origin", "\"" + pick.origin + "\" is not hand, proposed or corrected");
      }
      // A form given as null (a writer's empty value) is no form: said by
      // its field, not found missing later.
      for (const char* form : {"pixels", "points", "ends"})
        if (t.is_object() && t.contains(form) && t[form].is_null())
          r.fail(Reader::join(path, form), "must be an array, not null");
      const int forms = (t.contains("pixels") ? 1 : 0) + (t.contains("points") ? 1 : 0) +
                        (t.contains("ends") ? 1 : 0);
      if (forms != 1)
        r.fail(path,
               "give exactly one of \"pixels\" (taps), \"points\" (3D) or \"ends\" "
               "(semi-automatic)");
      if (auto* n = r.optional(t, path, "pair")) {
        pick.pair = r.integer(*n, path + ".pair");
        if (pick.pair < 1) r.fail(path + ".pair", "pairs are counted from 1");
        if (pick.pair > 1 && !t.contains("pixels"))
          r.fail(path + ".pair", "a further pair's trace is given as taps (\"pixels\")");
      }
      if (auto* px = r.optional(t, path, "pixels")) {
        pick.photo = photo(r, t, path);
        if (pick.pair > 1 && pick.photo != "left")
          r.fail(path + ".photo", "a further pair's trace is tapped in its left photograph");
        pick.pixels = pixels(r, *px, path + ".pixels");
        require_two_distinct(r, pick.pixels, path + ".pixels");
      } else if (auto* pts = r.optional(t, path, "points")) {
        r.array(*pts, path + ".points");
        for (std::size_t k = 0; k < pts->size(); ++k)
          pick.points.push_back(r.vec3((*pts)[k], Reader::index(path + ".points", k)));
        require_two_distinct(r, pick.points, path + ".points");
      } else {
        pick.photo = photo(r, t, path);
        const auto ends = pixels(r, r.require(t, path, "ends"), path + ".ends");
        if (ends.size() != 2)
          r.fail(path + ".ends", "needs the two end pixels, found " + std::to_string(ends.size()));
        require_two_distinct(r, ends, path + ".ends");
        pick.ends = std::array<Eigen::Vector2d, 2>{ends[0], ends[1]};
        if (auto* c = r.optional(t, path, "cost")) {
          pick.cost = r.string(*c, path + ".cost");
          if (pick.cost != "darkness" && pick.cost != "gradient" && pick.cost != "curvature")
            r.fail(path + ".cost", "\"" + pick.cost + "\" is not darkness, gradient or curvature");
        }
      }
      if (auto* c = r.optional(t, path, "compass"))
        pick.compass = compass(r, *c, path + ".compass");
      picks.traces.push_back(std::move(pick));
    }
  }
  if (auto* as = r.optional(object, top, "areas")) {
    r.array(*as, at("areas"));
    for (std::size_t i = 0; i < as->size(); ++i) {
      const json& a = (*as)[i];
      const std::string path = Reader::index(at("areas"), i);
      r.only_fields(a, path, {"id", "photo", "pair", "polygon", "rock_side"});
      AreaPick pick;
      pick.where = path;
      pick.id = r.id(r.require(a, path, "id"), path + ".id");
      unique(pick.id, path + ".id");
      pick.photo = photo(r, a, path);
      pick.pair = pair_of(r, a, path, pick.photo);
      pick.polygon = pixels(r, r.require(a, path, "polygon"), path + ".polygon");
      if (pick.polygon.size() < 3)
        r.fail(path + ".polygon",
               "a polygon needs at least 3 pixels, found " + std::to_string(pick.polygon.size()));
      if (auto* side = r.optional(a, path, "rock_side")) {
        pick.rock_side = r.string(*side, path + ".rock_side");
        if (pick.rock_side != "upper" && pick.rock_side != "lower")
          r.fail(path + ".rock_side", "\"" + pick.rock_side + "\" is not \"upper\" or \"lower\"");
      }
      picks.areas.push_back(std::move(pick));
    }
  }
  if (auto* ps = r.optional(object, top, "points")) {
    r.array(*ps, at("points"));
    for (std::size_t i = 0; i < ps->size(); ++i) {
      const json& p = (*ps)[i];
      const std::string path = Reader::index(at("points"), i);
      r.only_fields(p, path, {"id", "photo", "pair", "pixel", "radius"});
      PointPick pick;
      pick.where = path;
      pick.id = r.id(r.require(p, path, "id"), path + ".id");
      unique(pick.id, path + ".id");
      pick.photo = photo(r, p, path);
      pick.pair = pair_of(r, p, path, pick.photo);
      pick.pixel = pixel(r, r.require(p, path, "pixel"), path + ".pixel");
      if (auto* rad = r.optional(p, path, "radius"))
        pick.radius = r.positive(*rad, path + ".radius");
      picks.points.push_back(std::move(pick));
    }
  }
  if (auto* s = r.optional(object, top, "sets")) {
    if (s->is_string()) {
      if (s->get<std::string>() != "auto") r.fail(at("sets"), "must be a count or \"auto\"");
    } else {
      const int n = r.integer(*s, at("sets"));
      if (n < 1 || n > 12) r.fail(at("sets"), std::to_string(n) + " is outside [1, 12]");
      picks.sets = n;
    }
  }
  if (picks.traces.empty() && picks.areas.empty() && picks.points.empty())
    r.fail(top, "has no traces, areas or points");
  return picks;
}

Picks parse_picks(const std::string& text, const std::string& source) {
  const json doc = parse_json_naming_nan(text, source);
  const Reader r(source);
  if (!doc.is_object()) r.fail("(top level)", "must be a JSON object");
  const std::string format = r.string(r.require(doc, "", "format"), "format");
  if (format != "rockface-picks/1")
    r.fail("format", "\"" + format + "\" is not \"rockface-picks/1\"");
  return read_picks(doc, source, "");
}

Picks load_picks(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file, "cannot open the picks file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(file, "cannot read the picks file");
  return parse_picks(text.str(), file);
}

}  // namespace rockface::storage
