#include "storage/project/visit_geologist.h"

#include "core/common/error.h"

namespace rockface::storage {

std::string checked_geologist(const std::string& name, const std::string& field) {
  const auto first = name.find_first_not_of(' ');
  if (first == std::string::npos) return {};
  const std::string trimmed = name.substr(first, name.find_last_not_of(' ') - first + 1);
  for (unsigned char c : trimmed)
    if (c < 0x20 || c == 0x7f)
      throw InputError(field, "a geologist's name is one line of text (\"Anna Berger\")");
  // The name a reader shows for none must not be taken for a name.
  if (trimmed == kGeologistNotRecorded)
    throw InputError(field, std::string("\"") + kGeologistNotRecorded +
                                "\" stands for no geologist: give a name, or none");
  // Characters, not bytes: a UTF-8 name counts each of its letters once.
  std::size_t chars = 0;
  for (unsigned char c : trimmed) chars += (c & 0xC0) != 0x80;
  if (chars > kGeologistMaxChars)
    throw InputError(field, "a geologist's name has at most " + std::to_string(kGeologistMaxChars) +
                                " characters (\"" + trimmed.substr(0, 20) + "…\" has " +
                                std::to_string(chars) + ")");
  return trimmed;
}

}  // namespace rockface::storage
