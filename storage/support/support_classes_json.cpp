#include "storage/support/support_classes_json.h"

#include <fstream>
#include <set>
#include <sstream>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/tunnel/support_ranges.h"
#include "storage/json_reader.h"

namespace rockface::storage {

namespace {

using analysis::BoltPattern;
using analysis::FigureRange;
using analysis::SupportClass;
using analysis::SupportClasses;
using nlohmann::json;

// The figures' ranges as the tables allow them.
constexpr double kRmrLo = 0, kRmrHi = 100;
constexpr double kQLo = 0.001, kQHi = 1000;
// Shotcrete and the round: core/analysis/support_classes.h's ranges.
constexpr double kShotcreteMaxM = analysis::kShotcreteThicknessRange.hi;
constexpr double kShotcreteShearLo = analysis::kShotcreteShearRange.lo,
                 kShotcreteShearHi = analysis::kShotcreteShearRange.hi;
constexpr double kRoundMinM = analysis::kRoundLengthRange.lo,
                 kRoundMaxM = analysis::kRoundLengthRange.hi;

double in_range(const Reader& r, const json& v, const std::string& path,
                const tunnel::SupportRange& range, const char* what, double scale = 1) {
  const double d = r.number(v, path) * scale;
  if (!range.contains(d)) r.fail(path, tunnel::outside_range_text(d, range, what));
  return d;
}

BoltPattern read_bolts(const Reader& r, const json& o, const std::string& path) {
  r.only_fields(o, path, {"length_m", "spacing_m", "capacity_kn", "bond_kn_per_m"});
  BoltPattern b;
  b.length_m = in_range(r, r.require(o, path, "length_m"), Reader::join(path, "length_m"),
                        tunnel::kBoltLengthRange, "a bolt's length");
  b.spacing_m = in_range(r, r.require(o, path, "spacing_m"), Reader::join(path, "spacing_m"),
                         tunnel::kBoltSpacingRange, "a bolt pattern's spacing");
  b.capacity_n = in_range(r, r.require(o, path, "capacity_kn"), Reader::join(path, "capacity_kn"),
                          tunnel::kBoltCapacityRange, "a bolt's capacity", 1000);
  if (const auto* v = r.optional(o, path, "bond_kn_per_m"))
    b.bond_n_per_m = in_range(r, *v, Reader::join(path, "bond_kn_per_m"), tunnel::kBoltBondRange,
                              "a bolt's bond strength", 1000);
  return b;
}

FigureRange read_range(const Reader& r, const json& v, const std::string& path, double lo,
                       double hi) {
  if (!v.is_array() || v.size() != 2) r.fail(path, "must be [min, max] (null for an open end)");
  FigureRange out;
  if (!v[0].is_null()) out.min = r.number_in(v[0], path + "[0]", lo, hi);
  if (!v[1].is_null()) out.max = r.number_in(v[1], path + "[1]", lo, hi);
  if (out.min && out.max && !(*out.min < *out.max))
    r.fail(path, "min " + format_significant(*out.min, 4) + " is not below max " +
                     format_significant(*out.max, 4));
  return out;
}

std::string range_text(const char* figure, const FigureRange& f) {
  return std::string(figure) + " [" + (f.min ? format_significant(*f.min, 4) : "-") + ", " +
         (f.max ? format_significant(*f.max, 4) : "-") + ")";
}

// The classes' ranges of one figure: all or none, descending, neither
// overlapping nor leaving a gap.
void check_ranges(const Reader& r, const SupportClasses& s, const char* figure,
                  std::optional<FigureRange> analysis::SupportCriteria::*member, const char* key) {
  std::vector<std::string> with, without;
  for (const auto& c : s.classes) ((c.criteria.*member) ? with : without).push_back(c.name);
  if (with.empty()) return;
  for (std::size_t i = 0; i < s.classes.size(); ++i)
    if (!(s.classes[i].criteria.*member))
      r.fail("classes[" + std::to_string(i) + "].criteria." + key,
             "missing: class " + s.classes[i].name + " gives no " + figure + " range while " +
                 with.front() + " does (every class gives one, or none)");
  for (std::size_t i = 0; i + 1 < s.classes.size(); ++i) {
    const SupportClass& a = s.classes[i];
    const SupportClass& b = s.classes[i + 1];
    const FigureRange& fa = *(a.criteria.*member);
    const FigureRange& fb = *(b.criteria.*member);
    const std::string where = "classes[" + std::to_string(i + 1) + "].criteria." + key;
    if (!fa.min || !fb.max || *fb.max > *fa.min)
      r.fail(where, "class " + b.name + "'s " + range_text(figure, fb) + " overlaps class " +
                        a.name + "'s " + range_text(figure, fa) +
                        " (classes go from the lightest support, the highest " + figure +
                        ", to the heaviest)");
    if (*fb.max < *fa.min)
      r.fail(where, "no class covers " + std::string(figure) + " [" +
                        format_significant(*fb.max, 4) + ", " + format_significant(*fa.min, 4) +
                        "): a gap between class " + b.name + " and class " + a.name);
  }
}

json bolts_json(const BoltPattern& b) {
  json o = {
      {"length_m", b.length_m}, {"spacing_m", b.spacing_m}, {"capacity_kn", b.capacity_n / 1000}};
  if (b.bond_n_per_m) o["bond_kn_per_m"] = *b.bond_n_per_m / 1000;
  return o;
}

json range_json(const FigureRange& f) {
  return json::array({f.min ? json(*f.min) : json(nullptr), f.max ? json(*f.max) : json(nullptr)});
}

std::string read_classes_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), "cannot be read (missing or not permitted)");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

json parse_json(const std::string& text, const std::string& source) {
  try {
    return json::parse(text);
  } catch (const json::out_of_range&) {
    throw_number_overflow(text, source);
  } catch (const json::parse_error& e) {
    throw InputError(source, std::string("is not valid JSON: ") + e.what());
  }
}

}  // namespace

SupportClasses parse_support_classes(const std::string& text, const std::string& source) {
  const Reader r(source);
  const json doc = parse_json(text, source);
  if (!doc.is_object()) r.fail("(top level)", "must be an object with \"classes\"");
  r.only_fields(doc, "", {"format", "tunnel", "classes"});
  if (const auto* f = r.optional(doc, "", "format"))
    if (!f->is_string() || f->get<std::string>() != kSupportClassesFormat)
      r.fail("format", std::string("must be \"") + kSupportClassesFormat + "\"");
  SupportClasses out;
  out.source = source;
  if (const auto* t = r.optional(doc, "", "tunnel")) out.tunnel = r.string(*t, "tunnel");
  const json& list = r.array(r.require(doc, "", "classes"), "classes");
  if (list.empty()) r.fail("classes", "must list at least one class");
  std::set<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string p = Reader::index("classes", i);
    const json& o = list[i];
    r.only_fields(o, p,
                  {"name", "description", "round_length_m", "bolts", "shotcrete_m",
                   "shotcrete_shear_mpa", "mesh", "steel_sets", "face", "target_fos", "criteria"});
    SupportClass c;
    c.name = r.id(r.require(o, p, "name"), Reader::join(p, "name"));
    if (!names.insert(c.name).second)
      r.fail(Reader::join(p, "name"), "a second class named " + c.name);
    if (const auto* v = r.optional(o, p, "description"))
      c.description = r.string(*v, Reader::join(p, "description"));
    c.round_length_m = r.number_in(r.require(o, p, "round_length_m"),
                                   Reader::join(p, "round_length_m"), kRoundMinM, kRoundMaxM);
    if (const auto* v = r.optional(o, p, "bolts"))
      c.bolts = read_bolts(r, *v, Reader::join(p, "bolts"));
    if (const auto* v = r.optional(o, p, "shotcrete_m"))
      c.shotcrete_m = r.number_in(*v, Reader::join(p, "shotcrete_m"), 0, kShotcreteMaxM);
    if (const auto* v = r.optional(o, p, "shotcrete_shear_mpa"))
      c.shotcrete_shear_pa = 1e6 * r.number_in(*v, Reader::join(p, "shotcrete_shear_mpa"),
                                               kShotcreteShearLo / 1e6, kShotcreteShearHi / 1e6);
    if (const auto* v = r.optional(o, p, "mesh")) c.mesh = r.string(*v, Reader::join(p, "mesh"));
    if (const auto* v = r.optional(o, p, "steel_sets"))
      c.steel_sets = r.string(*v, Reader::join(p, "steel_sets"));
    if (const auto* v = r.optional(o, p, "face")) {
      const std::string fp = Reader::join(p, "face");
      r.only_fields(*v, fp, {"bolts", "shotcrete_m", "words"});
      if (const auto* b = r.optional(*v, fp, "bolts"))
        c.face.bolts = read_bolts(r, *b, Reader::join(fp, "bolts"));
      if (const auto* s = r.optional(*v, fp, "shotcrete_m"))
        c.face.shotcrete_m = r.number_in(*s, Reader::join(fp, "shotcrete_m"), 0, kShotcreteMaxM);
      if (const auto* w = r.optional(*v, fp, "words"))
        c.face.words = r.string(*w, Reader::join(fp, "words"));
    }
    if (const auto* v = r.optional(o, p, "target_fos"))
      c.target_fos = r.number_in(*v, Reader::join(p, "target_fos"), 1.0, 10.0);
    const std::string cp = Reader::join(p, "criteria");
    const json& k = r.require(o, p, "criteria");
    r.only_fields(k, cp, {"rmr", "q", "behaviour", "max_wedge_volume_m3", "max_wedge_apex_m"});
    if (const auto* v = r.optional(k, cp, "rmr"))
      c.criteria.rmr = read_range(r, *v, Reader::join(cp, "rmr"), kRmrLo, kRmrHi);
    if (const auto* v = r.optional(k, cp, "q"))
      c.criteria.q = read_range(r, *v, Reader::join(cp, "q"), kQLo, kQHi);
    if (const auto* v = r.optional(k, cp, "behaviour")) {
      const std::string bp = Reader::join(cp, "behaviour");
      const json& a = r.array(*v, bp);
      for (std::size_t j = 0; j < a.size(); ++j) {
        const std::string w = r.string(a[j], Reader::index(bp, j));
        if (w != analysis::kBehaviourStable && w != analysis::kBehaviourStructural)
          r.fail(Reader::index(bp, j), "\"" + w + "\" is not a behaviour (stable, structural)");
        c.criteria.behaviour.push_back(w);
      }
    }
    if (const auto* v = r.optional(k, cp, "max_wedge_volume_m3"))
      c.criteria.max_wedge_volume_m3 = r.positive(*v, Reader::join(cp, "max_wedge_volume_m3"));
    if (const auto* v = r.optional(k, cp, "max_wedge_apex_m"))
      c.criteria.max_wedge_apex_m = r.positive(*v, Reader::join(cp, "max_wedge_apex_m"));
    if (!c.criteria.rmr && !c.criteria.q && c.criteria.behaviour.empty() &&
        !c.criteria.max_wedge_volume_m3 && !c.criteria.max_wedge_apex_m)
      r.fail(cp, "class " + c.name + " states no criterion (rmr, q, behaviour, wedge sizes)");
    if (c.shotcrete_m > 0 && !c.shotcrete_shear_pa)
      r.fail(Reader::join(p, "shotcrete_shear_mpa"),
             "missing: class " + c.name + " has shotcrete; its shear strength counts it on wedges");
    out.classes.push_back(std::move(c));
  }
  check_ranges(r, out, "RMR", &analysis::SupportCriteria::rmr, "rmr");
  check_ranges(r, out, "Q", &analysis::SupportCriteria::q, "q");
  return out;
}

SupportClasses load_support_classes(const std::filesystem::path& file) {
  return parse_support_classes(read_classes_text(file), file.string());
}

json support_classes_json(const SupportClasses& s) {
  json list = json::array();
  for (const auto& c : s.classes) {
    json o = {{"name", c.name}, {"round_length_m", c.round_length_m}};
    if (!c.description.empty()) o["description"] = c.description;
    if (c.bolts) o["bolts"] = bolts_json(*c.bolts);
    if (c.shotcrete_m > 0) o["shotcrete_m"] = c.shotcrete_m;
    if (c.shotcrete_shear_pa) o["shotcrete_shear_mpa"] = *c.shotcrete_shear_pa / 1e6;
    if (!c.mesh.empty()) o["mesh"] = c.mesh;
    if (!c.steel_sets.empty()) o["steel_sets"] = c.steel_sets;
    json face = json::object();
    if (c.face.bolts) face["bolts"] = bolts_json(*c.face.bolts);
    if (c.face.shotcrete_m > 0) face["shotcrete_m"] = c.face.shotcrete_m;
    if (!c.face.words.empty()) face["words"] = c.face.words;
    if (!face.empty()) o["face"] = face;
    if (c.target_fos) o["target_fos"] = *c.target_fos;
    json k = json::object();
    if (c.criteria.rmr) k["rmr"] = range_json(*c.criteria.rmr);
    if (c.criteria.q) k["q"] = range_json(*c.criteria.q);
    if (!c.criteria.behaviour.empty()) k["behaviour"] = c.criteria.behaviour;
    if (c.criteria.max_wedge_volume_m3) k["max_wedge_volume_m3"] = *c.criteria.max_wedge_volume_m3;
    if (c.criteria.max_wedge_apex_m) k["max_wedge_apex_m"] = *c.criteria.max_wedge_apex_m;
    o["criteria"] = k;
    list.push_back(o);
  }
  json out = {{"format", kSupportClassesFormat}, {"classes", list}};
  if (!s.tunnel.empty()) out["tunnel"] = s.tunnel;
  return out;
}

json support_decision_json(const analysis::SupportDecision& d) {
  json changes = json::array();
  for (const auto& c : d.changes)
    changes.push_back({{"what", c.what}, {"from", c.from}, {"to", c.to}, {"reason", c.reason}});
  return {{"class", d.class_name}, {"proposed", d.proposed},     {"changes", changes},
          {"reason", d.reason},    {"decided_by", d.decided_by}, {"decided_at", d.decided_at},
          {"checks", d.checks}};
}

analysis::SupportDecision parse_support_decision(const std::string& text,
                                                 const std::string& source) {
  const Reader r(source);
  const json doc = parse_json(text, source);
  r.only_fields(doc, "",
                {"class", "proposed", "changes", "reason", "decided_by", "decided_at", "checks"});
  analysis::SupportDecision d;
  d.class_name = r.id(r.require(doc, "", "class"), "class");
  d.decided_by = r.id(r.require(doc, "", "decided_by"), "decided_by");
  d.decided_at = r.id(r.require(doc, "", "decided_at"), "decided_at");
  if (const auto* v = r.optional(doc, "", "proposed")) d.proposed = r.string(*v, "proposed");
  if (const auto* v = r.optional(doc, "", "reason")) d.reason = r.string(*v, "reason");
  if (const auto* v = r.optional(doc, "", "checks")) d.checks = r.string(*v, "checks");
  if (const auto* v = r.optional(doc, "", "changes")) {
    const json& a = r.array(*v, "changes");
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::string p = Reader::index("changes", i);
      r.only_fields(a[i], p, {"what", "from", "to", "reason"});
      analysis::SupportChange c;
      c.what = r.id(r.require(a[i], p, "what"), Reader::join(p, "what"));
      c.reason = r.id(r.require(a[i], p, "reason"), Reader::join(p, "reason"));
      if (const auto* f = r.optional(a[i], p, "from"))
        c.from = r.string(*f, Reader::join(p, "from"));
      if (const auto* t = r.optional(a[i], p, "to")) c.to = r.string(*t, Reader::join(p, "to"));
      d.changes.push_back(c);
    }
  }
  return d;
}

}  // namespace rockface::storage
