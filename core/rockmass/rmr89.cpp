#include "core/rockmass/rmr89.h"

#include <vector>

#include "core/common/number_format.h"

namespace rockface::rockmass {

namespace {

constexpr const char* kTableA1 = "Bieniawski 1989, Table 4.1 A.1 (strength of intact rock)";
constexpr const char* kTableA2 = "Bieniawski 1989, Table 4.1 A.2 (RQD)";
constexpr const char* kTableA3 = "Bieniawski 1989, Table 4.1 A.3 (spacing of discontinuities)";
constexpr const char* kTableA4 = "Bieniawski 1989, Table 4.1 A.4 (condition of discontinuities)";
constexpr const char* kTableE = "Bieniawski 1989, Table 4.1 E (condition of discontinuities)";
constexpr const char* kTableA5 = "Bieniawski 1989, Table 4.1 A.5 (groundwater)";
constexpr const char* kTableB = "Bieniawski 1989, Table 4.1 B (orientation adjustment, tunnels)";

// A total over lines each with its own [lowest, highest] rating.
struct Line {
  const Rating* rating;
  double lowest, highest;
};

Total total_of(const std::vector<Line>& lines) {
  Total t;
  for (const auto& l : lines) {
    if (l.rating->rating) {
      t.partial += *l.rating->rating;
      t.lowest += *l.rating->rating;
      t.highest += *l.rating->rating;
    } else {
      t.lowest += l.lowest;
      t.highest += l.highest;
      t.missing.push_back(l.rating->parameter);
    }
  }
  if (t.missing.empty()) t.value = t.partial;
  return t;
}

}  // namespace

double rmr_strength_ucs(double ucs) {
  if (ucs > 250) return 15;
  if (ucs >= 100) return 12;
  if (ucs >= 50) return 7;
  if (ucs >= 25) return 4;
  if (ucs >= 5) return 2;
  if (ucs >= 1) return 1;
  return 0;
}

std::optional<double> rmr_strength_is50(double is50) {
  if (is50 > 10) return 15;
  if (is50 >= 4) return 12;
  if (is50 >= 2) return 7;
  if (is50 >= 1) return 4;
  return std::nullopt;
}

double rmr_rqd(double rqd) {
  if (rqd >= 90) return 20;
  if (rqd >= 75) return 17;
  if (rqd >= 50) return 13;
  if (rqd >= 25) return 8;
  return 3;
}

double rmr_spacing(double s) {
  if (s > 2) return 20;
  if (s >= 0.6) return 15;
  if (s >= 0.2) return 10;
  if (s >= 0.06) return 8;
  return 5;
}

double rmr_persistence(double l) {
  if (l < 1) return 6;
  if (l < 3) return 4;
  if (l < 10) return 2;
  if (l <= 20) return 1;
  return 0;
}

double rmr_aperture(double a) {
  if (a <= 0) return 6;
  if (a < 0.1) return 5;
  if (a <= 1) return 4;
  if (a <= 5) return 1;
  return 0;
}

double rmr_roughness(Roughness r) {
  static constexpr double v[] = {6, 5, 3, 1, 0};
  return v[static_cast<int>(r)];
}
double rmr_infilling(Infilling i) {
  static constexpr double v[] = {6, 4, 2, 2, 0};
  return v[static_cast<int>(i)];
}
double rmr_weathering(Weathering w) {
  static constexpr double v[] = {6, 5, 3, 1, 0};
  return v[static_cast<int>(w)];
}
double rmr_groundwater(Groundwater g) {
  static constexpr double v[] = {15, 10, 7, 4, 0};
  return v[static_cast<int>(g)];
}
double rmr_inflow(double q) {
  if (q <= 0) return 15;
  if (q < 10) return 10;
  if (q <= 25) return 7;
  if (q <= 125) return 4;
  return 0;
}
double rmr_orientation(OrientationClass c) {
  static constexpr double v[] = {0, -2, -5, -10, -12};
  return v[static_cast<int>(c)];
}

int rmr_class(double r) {
  if (r > 80) return 1;
  if (r > 60) return 2;
  if (r > 40) return 3;
  if (r > 20) return 4;
  return 5;
}

const char* rmr_class_words(int c) {
  static constexpr const char* w[] = {"I very good rock", "II good rock", "III fair rock",
                                      "IV poor rock", "V very poor rock"};
  return w[c - 1];
}

const char* rmr_support(int c) {
  // Bieniawski 1989, Table 4.6 (10 m span, horseshoe, drill and blast,
  // vertical stress < 25 MPa), in the table's words.
  static constexpr const char* w[] = {
      "full face, 3 m advance; generally no support required except spot bolting",
      "full face, 1-1.5 m advance, complete support 20 m from face; locally bolts in crown 3 m "
      "long, spaced 2.5 m, with occasional wire mesh; 50 mm shotcrete in crown where required",
      "top heading and bench, 1.5-3 m advance in top heading, support after each blast, complete "
      "support 10 m from face; systematic bolts 4 m long, spaced 1.5-2 m in crown and walls with "
      "wire mesh in crown; 50-100 mm shotcrete in crown and 30 mm in sides",
      "top heading and bench, 1.0-1.5 m advance in top heading, support concurrently with "
      "excavation 10 m from face; systematic bolts 4-5 m long, spaced 1-1.5 m in crown and walls "
      "with wire mesh; 100-150 mm shotcrete in crown and 100 mm in sides; light to medium ribs "
      "spaced 1.5 m where required",
      "multiple drifts, 0.5-1.5 m advance in top heading, support concurrently with excavation, "
      "shotcrete as soon as possible after blasting; systematic bolts 5-6 m long, spaced 1-1.5 m "
      "in crown and walls with wire mesh, bolt invert; 150-200 mm shotcrete in crown, 150 mm in "
      "sides and 50 mm on face; medium to heavy ribs spaced 0.75 m with steel lagging and "
      "forepoling if required, close invert"};
  return w[c - 1];
}

Rmr89 rmr89(const MeasuredForRmr& m, const ClassificationForm& f) {
  validate(f);
  Rmr89 out;

  // A.1: the UCS where entered (the direct test), else the point-load index.
  Rating& a1 = out.strength;
  a1.parameter = "strength of intact rock";
  a1.unit = "MPa";
  a1.table = kTableA1;
  if (f.ucs_mpa) {
    a1.value = f.ucs_mpa;
    a1.value_words = "UCS " + format_fixed(*f.ucs_mpa, 0) + " MPa";
    a1.rating = rmr_strength_ucs(*f.ucs_mpa);
    a1.source = Source::entered;
    if (f.is50_mpa)
      a1.note = "rated on the UCS; Is50 " + format_fixed(*f.is50_mpa, 1) + " MPa entered";
  } else if (f.is50_mpa) {
    a1.value = f.is50_mpa;
    a1.value_words = "Is50 " + format_fixed(*f.is50_mpa, 1) + " MPa";
    a1.rating = rmr_strength_is50(*f.is50_mpa);
    a1.source = a1.rating ? Source::entered : Source::not_entered;
    if (!a1.rating) a1.note = "Is50 below 1 MPa: the table asks for the UCS";
  }

  Rating& a2 = out.rqd;
  a2.parameter = "RQD";
  a2.unit = "%";
  a2.table = kTableA2;
  if (m.rqd_percent) {
    a2.value = m.rqd_percent;
    a2.source = Source::measured;
    if (f.rqd_percent) a2.note = "entered " + format_fixed(*f.rqd_percent, 0) + " % not used";
  } else if (f.rqd_percent) {
    a2.value = f.rqd_percent;
    a2.source = Source::entered;
  }
  if (a2.value) {
    a2.rating = rmr_rqd(*a2.value);
    a2.value_words = format_fixed(*a2.value, 0) + " %";
  }

  Rating& a3 = out.spacing;
  a3.parameter = "spacing of discontinuities";
  a3.unit = "m";
  a3.table = kTableA3;
  if (m.spacing_m) {
    a3.value = m.spacing_m;
    a3.source = Source::measured;
    a3.value_words = format_fixed(*m.spacing_m, 2) + " m (" + m.spacing_set + ", the closest set)";
    if (f.spacing_m) a3.note = "entered " + format_fixed(*f.spacing_m, 2) + " m not used";
  } else if (f.spacing_m) {
    a3.value = f.spacing_m;
    a3.source = Source::entered;
    a3.value_words = format_fixed(*f.spacing_m, 2) + " m";
  }
  if (a3.value) a3.rating = rmr_spacing(*a3.value);

  // A.4: as a whole when rated so, else Table E's five parts.
  Rating& a4 = out.condition;
  a4.parameter = "condition of discontinuities";
  if (f.condition_rating) {
    a4.rating = f.condition_rating;
    a4.value = f.condition_rating;
    a4.source = Source::entered;
    a4.table = kTableA4;
    a4.value_words = "rated as a whole";
  } else {
    a4.table = kTableE;
    std::optional<double> persistence = m.persistence_m ? m.persistence_m : f.persistence_m;
    const bool persistence_measured = m.persistence_m.has_value();
    std::vector<std::string> open;
    double sum = 0;
    std::string parts;
    auto part = [&](const char* name, bool given, double r, const std::string& what) {
      if (!given) {
        open.push_back(name);
        return;
      }
      sum += r;
      parts += (parts.empty() ? "" : ", ") + what + " " + format_fixed(r, 0);
    };
    part("persistence", persistence.has_value(), persistence ? rmr_persistence(*persistence) : 0,
         persistence
             ? format_fixed(*persistence, 1) + " m" + (persistence_measured ? " (measured)" : "")
             : "");
    part("aperture", f.aperture_mm.has_value(), f.aperture_mm ? rmr_aperture(*f.aperture_mm) : 0,
         f.aperture_mm ? format_fixed(*f.aperture_mm, 1) + " mm" : "");
    part("roughness", f.roughness.has_value(), f.roughness ? rmr_roughness(*f.roughness) : 0,
         f.roughness ? words(*f.roughness) : "");
    part("infilling", f.infilling.has_value(), f.infilling ? rmr_infilling(*f.infilling) : 0,
         f.infilling ? words(*f.infilling) : "");
    part("weathering", f.weathering.has_value(), f.weathering ? rmr_weathering(*f.weathering) : 0,
         f.weathering ? words(*f.weathering) : "");
    a4.value_words = parts;
    if (open.empty()) {
      a4.rating = sum;
      a4.value = sum;
      a4.source = persistence_measured ? Source::mixed : Source::entered;
    } else {
      std::string list;
      for (const auto& o : open) list += (list.empty() ? "" : ", ") + o;
      a4.note = "not entered: " + list;
      if (persistence_measured && open.size() == 4)
        a4.note += " (persistence measured: " + format_fixed(*m.persistence_m, 1) + " m)";
    }
  }

  Rating& a5 = out.groundwater;
  a5.parameter = "groundwater";
  a5.table = kTableA5;
  if (f.groundwater) {
    a5.rating = rmr_groundwater(*f.groundwater);
    a5.value_words = words(*f.groundwater);
    a5.source = Source::entered;
    if (f.inflow_l_per_min) a5.note = "rated on the general condition; inflow entered beside it";
  } else if (f.inflow_l_per_min) {
    a5.value = f.inflow_l_per_min;
    a5.unit = "l/min per 10 m";
    a5.rating = rmr_inflow(*f.inflow_l_per_min);
    a5.value_words = format_fixed(*f.inflow_l_per_min, 0) + " l/min per 10 m of tunnel";
    a5.source = Source::entered;
  }

  Rating& b = out.orientation;
  b.parameter = "orientation adjustment (tunnels)";
  b.table = kTableB;
  if (m.orientation) {
    b.rating = rmr_orientation(*m.orientation);
    b.value_words = std::string(words(*m.orientation)) + " (" + m.orientation_words + ")";
    b.source = Source::measured;
    if (f.orientation) b.note = std::string("entered '") + words(*f.orientation) + "' not used";
  } else if (f.orientation) {
    b.rating = rmr_orientation(*f.orientation);
    b.value_words = words(*f.orientation);
    b.source = Source::entered;
  }

  out.basic = total_of({{&a1, 0, 15}, {&a2, 3, 20}, {&a3, 5, 20}, {&a4, 0, 30}, {&a5, 0, 15}});
  out.adjusted = total_of(
      {{&a1, 0, 15}, {&a2, 3, 20}, {&a3, 5, 20}, {&a4, 0, 30}, {&a5, 0, 15}, {&b, -12, 0}});
  if (out.adjusted.value) {
    out.rock_class = rmr_class(*out.adjusted.value);
    out.class_words = rmr_class_words(*out.rock_class);
  } else if (out.basic.value) {
    out.rock_class = rmr_class(*out.basic.value);
    out.class_words =
        std::string(rmr_class_words(*out.rock_class)) + " (basic RMR, orientation not adjusted)";
  }
  if (out.rock_class) out.support = rmr_support(*out.rock_class);
  return out;
}

}  // namespace rockface::rockmass
