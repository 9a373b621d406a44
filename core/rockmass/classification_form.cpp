#include "core/rockmass/classification_form.h"

#include <cmath>

#include "core/common/error.h"
#include "core/common/number_format.h"

namespace rockface::rockmass {

bool ClassificationForm::empty() const {
  return !ucs_mpa && !is50_mpa && !persistence_m && !aperture_mm && !roughness && !infilling &&
         !weathering && !condition_rating && !groundwater && !inflow_l_per_min && !rqd_percent &&
         !spacing_m && !orientation && !jn && !jr && !ja && !jw && !srf && !esr && !span_m;
}

const std::vector<FieldRange>& form_ranges() {
  // The ranges are the tables' own ends: a value outside cannot be rated.
  static const std::vector<FieldRange> ranges = {
      {"ucs_mpa", 0, 400, "Bieniawski 1989, Table A.1 (UCS)"},
      {"is50_mpa", 0, 20, "Bieniawski 1989, Table A.1 (point-load index)"},
      {"persistence_m", 0, 100, "Bieniawski 1989, Table E (discontinuity length)"},
      {"aperture_mm", 0, 100, "Bieniawski 1989, Table E (separation)"},
      {"condition_rating", 0, 30, "Bieniawski 1989, Table A.4 (condition of discontinuities)"},
      {"inflow_l_per_min", 0, 10000, "Bieniawski 1989, Table A.5 (inflow per 10 m tunnel length)"},
      {"rqd_percent", 0, 100, "Deere 1964 (RQD)"},
      {"spacing_m", 0, 100, "Bieniawski 1989, Table A.3 (spacing)"},
      {"Jn", 0.5, 20, "Barton 2002, Table Jn (joint set number)"},
      {"Jr", 0.5, 5, "Barton 2002, Table Jr (joint roughness number, +1 for spacing > 3 m)"},
      {"Ja", 0.75, 20, "Barton 2002, Table Ja (joint alteration number)"},
      {"Jw", 0.05, 1, "Barton 2002, Table Jw (joint water reduction factor)"},
      {"SRF", 0.5, 400, "Barton 2002, Table SRF (stress reduction factor)"},
      {"ESR", 0.5, 5, "Barton et al. 1974 / NGI 2015, Table ESR"},
      {"span_m", 0.5, 100, "span of the excavation"},
  };
  return ranges;
}

namespace {

void check(const std::optional<double>& v, const char* key) {
  if (!v) return;
  for (const auto& r : form_ranges()) {
    if (std::string(r.key) != key) continue;
    const std::string range = format_significant(r.min, 6) + "-" + format_significant(r.max, 6);
    if (!std::isfinite(*v))
      throw InputError(key, "is not a number (" + std::string(r.table) + " allows " + range + ")");
    if (*v < r.min || *v > r.max)
      throw InputError(key,
                       format_significant(*v, 6) + " is outside " + range + " (" + r.table + ")");
    return;
  }
}

template <class E, std::size_t N>
std::optional<E> from_words(const std::string& w, const char* const (&names)[N]) {
  for (std::size_t i = 0; i < N; ++i)
    if (w == names[i]) return static_cast<E>(i);
  return std::nullopt;
}

template <std::size_t N>
std::vector<std::string> all(const char* const (&names)[N]) {
  return std::vector<std::string>(names, names + N);
}

constexpr const char* kRoughness[] = {"very rough", "rough", "slightly rough", "smooth",
                                      "slickensided"};
constexpr const char* kInfilling[] = {"none", "hard filling < 5 mm", "hard filling > 5 mm",
                                      "soft filling < 5 mm", "soft filling > 5 mm"};
constexpr const char* kWeathering[] = {"unweathered", "slightly weathered", "moderately weathered",
                                       "highly weathered", "decomposed"};
constexpr const char* kGroundwater[] = {"completely dry", "damp", "wet", "dripping", "flowing"};
constexpr const char* kOrientation[] = {"very favourable", "favourable", "fair", "unfavourable",
                                        "very unfavourable"};

}  // namespace

void validate(const ClassificationForm& f) {
  check(f.ucs_mpa, "ucs_mpa");
  check(f.is50_mpa, "is50_mpa");
  check(f.persistence_m, "persistence_m");
  check(f.aperture_mm, "aperture_mm");
  check(f.condition_rating, "condition_rating");
  check(f.inflow_l_per_min, "inflow_l_per_min");
  check(f.rqd_percent, "rqd_percent");
  check(f.spacing_m, "spacing_m");
  check(f.jn, "Jn");
  check(f.jr, "Jr");
  check(f.ja, "Ja");
  check(f.jw, "Jw");
  check(f.srf, "SRF");
  check(f.esr, "ESR");
  check(f.span_m, "span_m");
}

const char* words(Roughness v) {
  return kRoughness[static_cast<int>(v)];
}
const char* words(Infilling v) {
  return kInfilling[static_cast<int>(v)];
}
const char* words(Weathering v) {
  return kWeathering[static_cast<int>(v)];
}
const char* words(Groundwater v) {
  return kGroundwater[static_cast<int>(v)];
}
const char* words(OrientationClass v) {
  return kOrientation[static_cast<int>(v)];
}
std::optional<Roughness> roughness_from(const std::string& w) {
  return from_words<Roughness>(w, kRoughness);
}
std::optional<Infilling> infilling_from(const std::string& w) {
  return from_words<Infilling>(w, kInfilling);
}
std::optional<Weathering> weathering_from(const std::string& w) {
  return from_words<Weathering>(w, kWeathering);
}
std::optional<Groundwater> groundwater_from(const std::string& w) {
  return from_words<Groundwater>(w, kGroundwater);
}
std::optional<OrientationClass> orientation_from(const std::string& w) {
  return from_words<OrientationClass>(w, kOrientation);
}
std::vector<std::string> roughness_words() {
  return all(kRoughness);
}
std::vector<std::string> infilling_words() {
  return all(kInfilling);
}
std::vector<std::string> weathering_words() {
  return all(kWeathering);
}
std::vector<std::string> groundwater_words() {
  return all(kGroundwater);
}
std::vector<std::string> orientation_words() {
  return all(kOrientation);
}

}  // namespace rockface::rockmass
