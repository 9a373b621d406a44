#pragma once
// The rock-mass classification form (core/rockmass/classification_form.h)
// as JSON: the scene's `rockmass` section, a FORM file for
// `rockface rockmass --form`, and the text the project stores per visit
// (docs/scene-extensions.md, "rockmass"). Keys are the form's field names
// (ucs_mpa, Jr, Ja, ...); words are the sheets' ("slightly rough", "damp").
// Unknown keys, unknown words and values out of a table's range are
// refused naming the file and field.
#include <string>

#include <nlohmann/json.hpp>

#include "core/rockmass/classification_form.h"
#include "storage/json_reader.h"

namespace rockface::storage {

nlohmann::json rockmass_form_json(const rockmass::ClassificationForm& form);

// Reads the object at `path` ("rockmass" in a scene, "" for a FORM file,
// whose `format` may be rockface-rockmass-form/1).
rockmass::ClassificationForm read_rockmass_form(const Reader& reader, const nlohmann::json& object,
                                                const std::string& path);
rockmass::ClassificationForm parse_rockmass_form(const std::string& text,
                                                 const std::string& source);
rockmass::ClassificationForm load_rockmass_form(const std::string& file);

}  // namespace rockface::storage
