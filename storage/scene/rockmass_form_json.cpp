#include "storage/scene/rockmass_form_json.h"

#include <fstream>
#include <optional>
#include <sstream>

#include "core/common/error.h"

namespace rockface::storage {

using rockmass::ClassificationForm;

namespace {

// The form's numeric fields by key, in the sheet's order.
struct NumberField {
  const char* key;
  std::optional<double> ClassificationForm::*field;
};
constexpr NumberField kNumbers[] = {
    {"ucs_mpa", &ClassificationForm::ucs_mpa},
    {"is50_mpa", &ClassificationForm::is50_mpa},
    {"persistence_m", &ClassificationForm::persistence_m},
    {"aperture_mm", &ClassificationForm::aperture_mm},
    {"condition_rating", &ClassificationForm::condition_rating},
    {"inflow_l_per_min", &ClassificationForm::inflow_l_per_min},
    {"rqd_percent", &ClassificationForm::rqd_percent},
    {"spacing_m", &ClassificationForm::spacing_m},
    {"Jn", &ClassificationForm::jn},
    {"Jr", &ClassificationForm::jr},
    {"Ja", &ClassificationForm::ja},
    {"Jw", &ClassificationForm::jw},
    {"SRF", &ClassificationForm::srf},
    {"ESR", &ClassificationForm::esr},
    {"span_m", &ClassificationForm::span_m},
};

template <class E>
std::optional<E> read_words(const Reader& r, const nlohmann::json& obj, const std::string& path,
                            const char* key, std::optional<E> (*from)(const std::string&),
                            std::vector<std::string> (*all)()) {
  const nlohmann::json* v = r.optional(obj, path, key);
  if (!v) return std::nullopt;
  const std::string w = r.string(*v, Reader::join(path, key));
  const auto e = from(w);
  if (!e) {
    std::string choices;
    for (const auto& c : all()) choices += (choices.empty() ? "\"" : ", \"") + c + "\"";
    r.fail(Reader::join(path, key), "\"" + w + "\" is not one of " + choices);
  }
  return e;
}

}  // namespace

nlohmann::json rockmass_form_json(const ClassificationForm& f) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& n : kNumbers)
    if (f.*(n.field)) j[n.key] = *(f.*(n.field));
  if (f.roughness) j["roughness"] = rockmass::words(*f.roughness);
  if (f.infilling) j["infilling"] = rockmass::words(*f.infilling);
  if (f.weathering) j["weathering"] = rockmass::words(*f.weathering);
  if (f.groundwater) j["groundwater"] = rockmass::words(*f.groundwater);
  if (f.orientation) j["orientation"] = rockmass::words(*f.orientation);
  if (!f.note.empty()) j["note"] = f.note;
  return j;
}

ClassificationForm read_rockmass_form(const Reader& r, const nlohmann::json& obj,
                                      const std::string& path) {
  if (!obj.is_object()) r.fail(path, "must be an object");
  ClassificationForm f;
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    const std::string& key = it.key();
    bool known = key == "format" || key == "note" || key == "roughness" || key == "infilling" ||
                 key == "weathering" || key == "groundwater" || key == "orientation";
    for (const auto& n : kNumbers) known = known || key == n.key;
    if (!known) r.fail(Reader::join(path, key.c_str()), "is not a field of the rock-mass form");
  }
  for (const auto& n : kNumbers)
    if (const auto* v = r.optional(obj, path, n.key))
      f.*(n.field) = r.number(*v, Reader::join(path, n.key));
  f.roughness =
      read_words(r, obj, path, "roughness", rockmass::roughness_from, rockmass::roughness_words);
  f.infilling =
      read_words(r, obj, path, "infilling", rockmass::infilling_from, rockmass::infilling_words);
  f.weathering =
      read_words(r, obj, path, "weathering", rockmass::weathering_from, rockmass::weathering_words);
  f.groundwater = read_words(r, obj, path, "groundwater", rockmass::groundwater_from,
                             rockmass::groundwater_words);
  f.orientation = read_words(r, obj, path, "orientation", rockmass::orientation_from,
                             rockmass::orientation_words);
  if (const auto* v = r.optional(obj, path, "note"))
    f.note = r.string(*v, Reader::join(path, "note"));
  try {
    rockmass::validate(f);
  } catch (const InputError& e) {
    r.fail(Reader::join(path, e.where().c_str()), e.reason());
  }
  return f;
}

ClassificationForm parse_rockmass_form(const std::string& text, const std::string& source) {
  const nlohmann::json doc = parse_json_naming_nan(text, source);
  Reader r(source);
  if (const auto* format = doc.is_object() ? r.optional(doc, "", "format") : nullptr)
    if (r.string(*format, "format") != "rockface-rockmass-form/1")
      r.fail("format", "must be \"rockface-rockmass-form/1\"");
  return read_rockmass_form(r, doc, "");
}

ClassificationForm load_rockmass_form(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file, "cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_rockmass_form(text.str(), file);
}

}  // namespace rockface::storage
