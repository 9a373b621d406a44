#include "core/rockmass/figures_in_words.h"

#include <cmath>
#include <cstdio>

namespace rockface::rockmass {

namespace {

std::string fmt(const char* format, double v) {
  char text[64];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

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
    line += fmt("%g", *r.rating) + " (" + words(r.source) + "; " + r.table + ")";
  }
  if (!r.note.empty()) line += "; " + r.note;
  return line;
}

std::string rmr_line(const Rmr89& r) {
  if (r.adjusted.value)
    return "RMR89 " + fmt("%.0f", *r.adjusted.value) + " (" + r.class_words + "), basic " +
           fmt("%.0f", *r.basic.value);
  if (r.basic.value)
    return "RMR89 basic " + fmt("%.0f", *r.basic.value) + " (" + r.class_words +
           "); orientation adjustment not entered";
  return "RMR89 incomplete: " + fmt("%.0f", r.adjusted.partial) + " so far, " +
         fmt("%.0f", r.adjusted.lowest) + "-" + fmt("%.0f", r.adjusted.highest) + " with " +
         list(r.adjusted.missing) + " not entered";
}

std::string q_line(const QSystem& q) {
  if (q.q) return "Q " + fmt("%.3g", *q.q) + " (" + q.class_words + ")";
  return "Q incomplete: between " + fmt("%.2g", *q.q_lowest) + " and " + fmt("%.3g", *q.q_highest) +
         " with " + list(q.missing) + " not entered";
}

std::vector<std::string> figures_lines(const RockMassFigures& f) {
  std::vector<std::string> out;
  out.push_back(std::to_string(f.assigned.set_of.size()) + " traces on a face window of " +
                fmt("%.1f", f.window.area_m2) + " m2: " + std::to_string(f.sets) + " sets, " +
                std::to_string(f.assigned.random.size()) + " random");
  for (std::size_t k = 0; k < f.spacings.size(); ++k) {
    const auto& s = f.spacings[k];
    std::string line = s.label + ": " + std::to_string(s.traces) + " traces, ";
    if (s.mean_m)
      line += "normal spacing " + fmt("%.2f m", *s.mean_m) + " (median " +
              fmt("%.2f", *s.median_m) + ", " + fmt("%.2f", *s.min_m) + "-" +
              fmt("%.2f m", *s.max_m) + "), " + s.distribution;
    else
      line += s.distribution;
    line += ", " + fmt("%.0f deg to the face, Terzaghi weight ", s.face_angle_deg) +
            fmt("%.2f", s.terzaghi_weight);
    if (k < f.persistence.size()) {
      const auto& p = f.persistence[k];
      if (p.persistence_m)
        line += "; persistence " + fmt("%.1f m", *p.persistence_m) + " (" + p.isrm_words + ")";
      else if (p.lower_bound_m)
        line += "; persistence at least " + fmt("%.1f m", *p.lower_bound_m) + " (" +
                std::to_string(p.censored) + " of " + std::to_string(p.traces) + " censored)";
    }
    out.push_back(line);
  }
  for (const auto& d : f.scanlines.directions) {
    std::string line = "scanlines " + d.name + ": " + std::to_string(d.lines) + " lines, " +
                       fmt("%.1f m", d.length_m) + ", " + fmt("%.2f per m", d.frequency_per_m);
    if (d.rqd_percent) line += ", RQD " + fmt("%.0f %%", *d.rqd_percent);
    if (d.priest_hudson_from_frequency)
      line += " (Priest-Hudson from the count " + fmt("%.0f %%", *d.priest_hudson_from_frequency);
    if (d.priest_hudson_from_spacing)
      line += ", from the sets' spacing " + fmt("%.0f %%", *d.priest_hudson_from_spacing);
    if (d.priest_hudson_from_frequency) line += ")";
    out.push_back(line);
  }
  if (f.scanlines.rqd_percent)
    out.push_back("RQD " + fmt("%.0f %%", *f.scanlines.rqd_percent) + " (mean of the directions, " +
                  "lowest " + fmt("%.0f %%", *f.scanlines.lowest_percent) + ")");
  if (f.jv.jv)
    out.push_back("Jv " + fmt("%.2f joints per m3", *f.jv.jv) + " (sets " +
                  fmt("%.2f", f.jv.from_sets) + ", random " + fmt("%.2f", f.jv.from_random) +
                  "); Palmström's RQD from Jv " + fmt("%.0f %%", *f.jv.rqd_palmstrom));
  const auto& b = f.blocks;
  if (b.finite_blocks > 0)
    out.push_back(std::to_string(b.finite_blocks) + " finite blocks on the face: V50 " +
                  fmt("%.3g m3", *b.v50_m3) + ", mean " + fmt("%.3g m3", *b.mean_m3) + ", " +
                  fmt("%.3g", *b.min_m3) + "-" + fmt("%.3g m3", *b.max_m3) +
                  (b.shape_of_blocks ? ", shape " + b.shape_of_blocks->words +
                                           fmt(" (beta %.0f)", b.shape_of_blocks->beta)
                                     : ""));
  if (b.vb_from_spacing_m3)
    out.push_back("Vb from the spacing of " + list(b.spacing_sets) + ": " +
                  fmt("%.3g m3", *b.vb_from_spacing_m3) + ", shape " + b.shape_from_spacing->words +
                  fmt(" (alpha2 %.1f", b.shape_from_spacing->alpha2) +
                  fmt(", alpha3 %.1f", b.shape_from_spacing->alpha3) +
                  fmt(", beta %.0f)", b.shape_from_spacing->beta));
  if (b.vb_from_jv_m3) out.push_back("Vb from Jv: " + fmt("%.3g m3", *b.vb_from_jv_m3));
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
    out.push_back("  " + d.label + " against the drive: " + d.words +
                  fmt(" (margin %.1f deg)", d.margin_deg));
  const QSystem& q = f.q;
  out.push_back(q_line(q));
  for (const Rating* x : {&q.rqd, &q.jn, &q.jr, &q.ja, &q.jw, &q.srf})
    out.push_back("  " + rating_line(*x));
  if (!q.support.empty()) out.push_back("  support (Barton 1974/2002): " + q.support);
  return out;
}

}  // namespace rockface::rockmass
