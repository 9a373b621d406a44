#include "core/rockmass/figures_in_words.h"

#include <cmath>

#include "core/common/number_format.h"

namespace rockface::rockmass {

namespace {

std::string list(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& i : items) out += (out.empty() ? "" : ", ") + i;
  return out;
}

}  // namespace

const char* words(Source s) {
  switch (s) {
    case Source::measured:
      return "measured";
    case Source::entered:
      return "entered";
    case Source::mixed:
      return "measured + entered";
    case Source::not_entered:
      return "not entered";
  }
  return "not entered";
}

std::string rating_line(const Rating& r) {
  std::string line = r.parameter + ": ";
  if (!r.rating) {
    line += std::string("not entered (") + r.table + ")";
  } else {
    if (!r.value_words.empty()) line += r.value_words + " -> ";
    line += format_significant(*r.rating, 6) + " (" + words(r.source) + "; " + r.table + ")";
  }
  if (!r.note.empty()) line += "; " + r.note;
  return line;
}

std::string rmr_line(const Rmr89& r) {
  if (r.adjusted.value)
    return "RMR89 " + format_fixed(*r.adjusted.value, 0) + " (" + r.class_words + "), basic " +
           format_fixed(*r.basic.value, 0);
  if (r.basic.value)
    return "RMR89 basic " + format_fixed(*r.basic.value, 0) + " (" + r.class_words +
           "); orientation adjustment not entered";
  return "RMR89 incomplete: " + format_fixed(r.adjusted.partial, 0) + " so far, " +
         format_fixed(r.adjusted.lowest, 0) + "-" + format_fixed(r.adjusted.highest, 0) + " with " +
         list(r.adjusted.missing) + " not entered";
}

std::string q_line(const QSystem& q) {
  if (q.q) return "Q " + format_significant(*q.q, 3) + " (" + q.class_words + ")";
  return "Q incomplete: between " + format_significant(*q.q_lowest, 2) + " and " +
         format_significant(*q.q_highest, 3) + " with " + list(q.missing) + " not entered";
}

std::vector<std::string> figures_lines(const RockMassFigures& f) {
  std::vector<std::string> out;
  out.push_back(std::to_string(f.assigned.set_of.size()) + " traces on a face window of " +
                format_fixed(f.window.area_m2, 1) + " m²: " + std::to_string(f.sets) + " sets, " +
                std::to_string(f.assigned.random.size()) + " random");
  for (std::size_t k = 0; k < f.spacings.size(); ++k) {
    const auto& s = f.spacings[k];
    std::string line = s.label + ": " + std::to_string(s.traces) + " traces, ";
    if (s.mean_m)
      line += "normal spacing " + format_fixed(*s.mean_m, 2, " m") + " (median " +
              format_fixed(*s.median_m, 2) + ", " + format_fixed(*s.min_m, 2) + "-" +
              format_fixed(*s.max_m, 2, " m") + "), " + s.distribution;
    else
      line += s.distribution;
    line += ", " + format_fixed(s.face_angle_deg, 0, " deg") + " to the face, Terzaghi weight " +
            format_fixed(s.terzaghi_weight, 2);
    if (k < f.persistence.size()) {
      const auto& p = f.persistence[k];
      if (p.persistence_m)
        line +=
            "; persistence " + format_fixed(*p.persistence_m, 1, " m") + " (" + p.isrm_words + ")";
      else if (p.lower_bound_m)
        line += "; persistence at least " + format_fixed(*p.lower_bound_m, 1, " m") + " (" +
                std::to_string(p.censored) + " of " + std::to_string(p.traces) + " censored)";
    }
    out.push_back(line);
  }
  for (const auto& d : f.scanlines.directions) {
    std::string line = "scanlines " + d.name + ": " + std::to_string(d.lines) + " lines, " +
                       format_fixed(d.length_m, 1, " m") + ", " +
                       format_fixed(d.frequency_per_m, 2, " per m");
    if (d.rqd_percent) line += ", RQD " + format_fixed(*d.rqd_percent, 0, " %");
    if (d.priest_hudson_from_frequency)
      line += " (Priest-Hudson from the count " +
              format_fixed(*d.priest_hudson_from_frequency, 0, " %");
    if (d.priest_hudson_from_spacing)
      line += ", from the sets' spacing " + format_fixed(*d.priest_hudson_from_spacing, 0, " %");
    if (d.priest_hudson_from_frequency) line += ")";
    out.push_back(line);
  }
  if (f.scanlines.rqd_percent)
    out.push_back("RQD " + format_fixed(*f.scanlines.rqd_percent, 0, " %") +
                  " (mean of the directions, " + "lowest " +
                  format_fixed(*f.scanlines.lowest_percent, 0, " %") + ")");
  if (f.jv.jv)
    out.push_back("Jv " + format_fixed(*f.jv.jv, 2, " joints per m³") + " (sets " +
                  format_fixed(f.jv.from_sets, 2) + ", random " +
                  format_fixed(f.jv.from_random, 2) + "); Palmström's RQD from Jv " +
                  format_fixed(*f.jv.rqd_palmstrom, 0, " %"));
  const auto& b = f.blocks;
  if (b.finite_blocks > 0)
    out.push_back(std::to_string(b.finite_blocks) + " finite blocks on the face: V50 " +
                  format_significant(*b.v50_m3, 3, " m³") + ", mean " +
                  format_significant(*b.mean_m3, 3, " m³") + ", " +
                  format_significant(*b.min_m3, 3) + "-" + format_significant(*b.max_m3, 3, " m³") +
                  (b.shape_of_blocks ? ", shape " + b.shape_of_blocks->words + " (beta " +
                                           format_fixed(b.shape_of_blocks->beta, 0) + ")"
                                     : ""));
  if (b.vb_from_spacing_m3)
    out.push_back("Vb from the spacing of " + list(b.spacing_sets) + ": " +
                  format_significant(*b.vb_from_spacing_m3, 3, " m³") + ", shape " +
                  b.shape_from_spacing->words + " (alpha2 " +
                  format_fixed(b.shape_from_spacing->alpha2, 1) + ", alpha3 " +
                  format_fixed(b.shape_from_spacing->alpha3, 1) + ", beta " +
                  format_fixed(b.shape_from_spacing->beta, 0) + ")");
  if (b.vb_from_jv_m3)
    out.push_back("Vb from Jv: " + format_significant(*b.vb_from_jv_m3, 3, " m³"));
  if (!b.size_words.empty()) out.push_back("block size: " + b.size_words);
  for (const auto& n : f.notes) out.push_back(n);
  return out;
}

std::vector<std::string> classification_lines(const RockMassFigures& f) {
  std::vector<std::string> out;
  const Rmr89& r = f.rmr;
  out.push_back(rmr_line(r));
  for (const Rating* x :
       {&r.strength, &r.rqd, &r.spacing, &r.condition, &r.groundwater, &r.orientation})
    out.push_back("  " + rating_line(*x));
  if (!r.support.empty()) out.push_back("  support (Bieniawski 1989, Table 4.6): " + r.support);
  for (const auto& d : f.drive)
    out.push_back("  " + d.label + " against the drive: " + d.words + " (margin " +
                  format_fixed(d.margin_deg, 1, " deg") + ")");
  const QSystem& q = f.q;
  out.push_back(q_line(q));
  for (const Rating* x : {&q.rqd, &q.jn, &q.jr, &q.ja, &q.jw, &q.srf})
    out.push_back("  " + rating_line(*x));
  if (!q.support.empty()) out.push_back("  support (Barton 1974/2002): " + q.support);
  return out;
}

}  // namespace rockface::rockmass
