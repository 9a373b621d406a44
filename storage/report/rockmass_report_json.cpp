#include "storage/report/rockmass_report_json.h"

#include <cmath>

#include "storage/scene/rockmass_form_json.h"

namespace rockface::storage {

using nlohmann::json;
using namespace rockmass;

namespace {

// Six significant digits: the figures are measurements, not bit patterns.
double tidy_rockmass(double v) {
  if (v == 0 || !std::isfinite(v)) return v;
  const double scale = std::pow(10.0, 5 - std::floor(std::log10(std::abs(v))));
  return std::round(v * scale) / scale;
}
json opt(const std::optional<double>& v) {
  return v ? json(tidy_rockmass(*v)) : json(nullptr);
}
json vec_rockmass(const Eigen::Vector3d& v) {
  return {tidy_rockmass(v.x()), tidy_rockmass(v.y()), tidy_rockmass(v.z())};
}

json histogram(const Histogram& h) {
  json edges = json::array();
  for (double e : h.edges) edges.push_back(tidy_rockmass(e));
  return {{"edges", edges}, {"counts", h.counts}};
}

json rating(const Rating& r) {
  json j = {{"parameter", r.parameter},
            {"rating", opt(r.rating)},
            {"source", words(r.source)},
            {"table", r.table}};
  if (r.value) j["value"] = tidy_rockmass(*r.value);
  if (!r.unit.empty()) j["unit"] = r.unit;
  if (!r.value_words.empty()) j["value_words"] = r.value_words;
  if (!r.note.empty()) j["note"] = r.note;
  return j;
}

json total(const Total& t) {
  return {{"value", opt(t.value)},
          {"complete", t.value.has_value()},
          {"partial", tidy_rockmass(t.partial)},
          {"lowest", tidy_rockmass(t.lowest)},
          {"highest", tidy_rockmass(t.highest)},
          {"missing", t.missing}};
}

json shape(const std::optional<BlockShape>& s) {
  if (!s) return nullptr;
  return {{"alpha2", tidy_rockmass(s->alpha2)},
          {"alpha3", tidy_rockmass(s->alpha3)},
          {"beta", tidy_rockmass(s->beta)},
          {"words", s->words}};
}

}  // namespace

json rockmass_report_json(const RockMassFigures& f) {
  json j;
  j["format"] = "rockface-rockmass/1";
  j["window"] = {{"area_m2", tidy_rockmass(f.window.area_m2)},
                 {"normal", vec_rockmass(f.window.normal)},
                 {"horizontal", vec_rockmass(f.window.h)},
                 {"up", vec_rockmass(f.window.v)}};
  j["traces"] = {{"count", f.assigned.set_of.size()},
                 {"random", f.assigned.random.size()},
                 {"assigned_by", f.assigned.how}};
  json sets = json::array();
  for (std::size_t k = 0; k < f.spacings.size(); ++k) {
    const auto& s = f.spacings[k];
    json gaps = json::array();
    for (double g : s.gaps_m) gaps.push_back(tidy_rockmass(g));
    json set = {{"label", s.label},
                {"traces", s.traces},
                {"discontinuities", s.discontinuities},
                {"spacing",
                 {{"mean_m", opt(s.mean_m)},
                  {"median_m", opt(s.median_m)},
                  {"std_m", opt(s.std_m)},
                  {"cv", opt(s.cv)},
                  {"min_m", opt(s.min_m)},
                  {"max_m", opt(s.max_m)},
                  {"p10_m", opt(s.p10_m)},
                  {"p90_m", opt(s.p90_m)},
                  {"gaps_m", gaps},
                  {"distribution", s.distribution},
                  {"histogram", histogram(s.histogram)},
                  {"apparent_on_face_m", opt(s.apparent_on_face_m)}}},
                {"terzaghi",
                 {{"face_angle_deg", tidy_rockmass(s.face_angle_deg)},
                  {"weight", tidy_rockmass(s.terzaghi_weight)},
                  {"weighted_count", tidy_rockmass(s.weighted_count)},
                  {"blind_zone", s.in_blind_zone}}}};
    if (k < f.persistence.size()) {
      const auto& p = f.persistence[k];
      set["persistence"] = {{"traces", p.traces},
                            {"censored", p.censored},
                            {"mean_all_m", opt(p.mean_all_m)},
                            {"mean_uncensored_m", opt(p.mean_uncensored_m)},
                            {"longest_m", opt(p.longest_m)},
                            {"persistence_m", opt(p.persistence_m)},
                            {"lower_bound_m", opt(p.lower_bound_m)},
                            {"words", p.isrm_words},
                            {"censoring", p.censoring}};
    }
    sets.push_back(set);
  }
  j["sets"] = sets;

  json dirs = json::array();
  for (const auto& d : f.scanlines.directions) {
    json per_set = json::array();
    for (const auto& s : d.sets)
      per_set.push_back({{"label", s.label},
                         {"crossings", s.crossings},
                         {"cos_delta", tidy_rockmass(s.cos_delta)},
                         {"blind_zone", s.in_blind_zone},
                         {"apparent_spacing_m", opt(s.apparent_m)},
                         {"terzaghi_spacing_m", opt(s.corrected_m)}});
    dirs.push_back({{"name", d.name},
                    {"angle_deg", d.angle_deg},
                    {"direction", vec_rockmass(d.direction)},
                    {"lines", d.lines},
                    {"length_m", tidy_rockmass(d.length_m)},
                    {"crossings", d.crossings},
                    {"frequency_per_m", tidy_rockmass(d.frequency_per_m)},
                    {"rqd_percent", opt(d.rqd_percent)},
                    {"priest_hudson_from_frequency", opt(d.priest_hudson_from_frequency)},
                    {"frequency_from_sets_per_m", opt(d.frequency_from_sets_per_m)},
                    {"priest_hudson_from_spacing", opt(d.priest_hudson_from_spacing)},
                    {"sets", per_set}});
  }
  j["rqd"] = {{"scanlines", dirs},
              {"rqd_percent", opt(f.scanlines.rqd_percent)},
              {"lowest_percent", opt(f.scanlines.lowest_percent)},
              {"priest_hudson_from_spacing", opt(f.scanlines.priest_hudson_from_spacing)}};
  j["jv"] = {{"per_m3", opt(f.jv.jv)},
             {"from_sets", tidy_rockmass(f.jv.from_sets)},
             {"from_random", tidy_rockmass(f.jv.from_random)},
             {"sets_used", f.jv.sets_used},
             {"random_traces", f.jv.random_traces},
             {"window_area_m2", tidy_rockmass(f.jv.window_area_m2)},
             {"rqd_palmstrom", opt(f.jv.rqd_palmstrom)},
             {"sets_without_spacing", f.jv.sets_without_spacing}};
  const auto& b = f.blocks;
  json volumes = json::array();
  for (double v : b.volumes_m3) volumes.push_back(tidy_rockmass(v));
  j["blocks"] = {{"finite_blocks", b.finite_blocks},
                 {"volumes_m3", volumes},
                 {"histogram", histogram(b.histogram)},
                 {"v50_m3", opt(b.v50_m3)},
                 {"mean_m3", opt(b.mean_m3)},
                 {"min_m3", opt(b.min_m3)},
                 {"max_m3", opt(b.max_m3)},
                 {"shape_of_blocks", shape(b.shape_of_blocks)},
                 {"vb_from_spacing_m3", opt(b.vb_from_spacing_m3)},
                 {"shape_from_spacing", shape(b.shape_from_spacing)},
                 {"spacing_sets", b.spacing_sets},
                 {"vb_from_jv_m3", opt(b.vb_from_jv_m3)},
                 {"size_words", b.size_words}};
  if (!b.note.empty()) j["blocks"]["note"] = b.note;

  json drive = json::array();
  for (const auto& d : f.drive)
    drive.push_back({{"label", d.label},
                     {"class", words(d.cls)},
                     {"words", d.words},
                     {"margin_deg", tidy_rockmass(d.margin_deg)},
                     {"marginal", d.marginal}});
  const Rmr89& r = f.rmr;
  j["rmr89"] = {{"strength", rating(r.strength)},
                {"rqd", rating(r.rqd)},
                {"spacing", rating(r.spacing)},
                {"condition", rating(r.condition)},
                {"groundwater", rating(r.groundwater)},
                {"orientation", rating(r.orientation)},
                {"basic", total(r.basic)},
                {"adjusted", total(r.adjusted)},
                {"class", r.rock_class ? json(*r.rock_class) : json(nullptr)},
                {"class_words", r.class_words},
                {"support", r.support},
                {"sets_against_drive", drive}};
  const QSystem& q = f.q;
  j["q"] = {{"rqd", rating(q.rqd)},
            {"jn", rating(q.jn)},
            {"jr", rating(q.jr)},
            {"ja", rating(q.ja)},
            {"jw", rating(q.jw)},
            {"srf", rating(q.srf)},
            {"value", opt(q.q)},
            {"complete", q.q.has_value()},
            {"lowest", opt(q.q_lowest)},
            {"highest", opt(q.q_highest)},
            {"missing", q.missing},
            {"class_words", q.class_words},
            {"equivalent_dimension", opt(q.equivalent_dimension)},
            {"max_unsupported_span_m", opt(q.max_unsupported_span_m)},
            {"bolt_length_m", opt(q.bolt_length_m)},
            {"roof_pressure_kpa", opt(q.roof_pressure_kpa)},
            {"support", q.support}};
  j["form"] = rockmass_form_json(f.form);
  j["notes"] = f.notes;
  return j;
}

}  // namespace rockface::storage
