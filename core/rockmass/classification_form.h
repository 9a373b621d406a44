#pragma once
// The classification sheet's parameters that the photograph cannot give,
// as the geologist enters them on site (RMR89: intact strength, condition of
// discontinuities, groundwater; Q: Jr, Ja, Jw, SRF; the support figures'
// ESR and span). Every field is optional: a field left empty is "not
// entered", never a default. A few measured figures may also be entered
// (RQD, spacing, persistence, Jn, the orientation class) for a visit whose
// photographs do not give them; a measured value always wins and the
// entered one is then reported beside it.
//
// validate() checks each entered value against its table's range and
// refuses the first one out of range by name (InputError, field = the
// form's key, e.g. "Ja").
#include <optional>
#include <string>
#include <vector>

namespace rockface::rockmass {

// Bieniawski 1989, Table E (guidelines for the condition of discontinuities).
enum class Roughness { very_rough, rough, slightly_rough, smooth, slickensided };
enum class Infilling { none, hard_under_5mm, hard_over_5mm, soft_under_5mm, soft_over_5mm };
enum class Weathering { unweathered, slightly, moderately, highly, decomposed };
// Bieniawski 1989, Table A.5 (general conditions).
enum class Groundwater { completely_dry, damp, wet, dripping, flowing };
// Bieniawski 1989, Table B (effect of discontinuity orientations, tunnels).
enum class OrientationClass { very_favourable, favourable, fair, unfavourable, very_unfavourable };

struct ClassificationForm {
  // Intact rock: uniaxial compressive strength or point-load index (MPa).
  std::optional<double> ucs_mpa, is50_mpa;
  // Condition of discontinuities: Table E's five parts...
  std::optional<double> persistence_m, aperture_mm;
  std::optional<Roughness> roughness;
  std::optional<Infilling> infilling;
  std::optional<Weathering> weathering;
  // ... or Table A.4's rating as a whole (0-30), when the geologist rates it so.
  std::optional<double> condition_rating;
  // Groundwater: the general condition, or the inflow per 10 m of tunnel (l/min).
  std::optional<Groundwater> groundwater;
  std::optional<double> inflow_l_per_min;
  // Only for a visit whose photographs do not give them (see above).
  std::optional<double> rqd_percent, spacing_m;
  std::optional<OrientationClass> orientation;
  std::optional<double> jn;
  // Q (Barton et al. 1974, Barton 2002).
  std::optional<double> jr, ja, jw, srf;
  // Support figures: excavation support ratio and span (m; a tunnel's
  // design profile gives its width).
  std::optional<double> esr, span_m;
  std::string note;

  bool empty() const;
};

// The range a field's table allows, in words ("0.75-20 (Barton 2002, Ja)").
struct FieldRange {
  const char* key;  // "Ja", "ucs_mpa", ...
  double min, max;
  const char* table;
};
const std::vector<FieldRange>& form_ranges();

// Throws InputError(key, "<value> is outside <min>-<max> (<table>)") for the
// first entered value out of its range or not finite.
void validate(const ClassificationForm& form);

// The words of the enums as the sheets print them, and back (nullopt for
// unknown words).
const char* words(Roughness v);
const char* words(Infilling v);
const char* words(Weathering v);
const char* words(Groundwater v);
const char* words(OrientationClass v);
std::optional<Roughness> roughness_from(const std::string& w);
std::optional<Infilling> infilling_from(const std::string& w);
std::optional<Weathering> weathering_from(const std::string& w);
std::optional<Groundwater> groundwater_from(const std::string& w);
std::optional<OrientationClass> orientation_from(const std::string& w);
// All the words of one enum, in table order (for the form's choices).
std::vector<std::string> roughness_words();
std::vector<std::string> infilling_words();
std::vector<std::string> weathering_words();
std::vector<std::string> groundwater_words();
std::vector<std::string> orientation_words();

}  // namespace rockface::rockmass
