#include "storage/project/one_line_name.h"

#include "core/common/error.h"

namespace rockface::storage {

std::string checked_one_line_name(const std::string& name, const OneLineNameRule& rule,
                                  const std::string& field) {
  const auto first = name.find_first_not_of(' ');
  if (first == std::string::npos) return {};
  const std::string trimmed = name.substr(first, name.find_last_not_of(' ') - first + 1);
  for (unsigned char c : trimmed)
    if (c < 0x20 || c == 0x7f)
      throw InputError(field, rule.what + " is one line of text " + rule.examples);
  // The text a reader shows for none must not be taken for a name.
  if (trimmed == rule.none)
    throw InputError(field, "\"" + rule.none + "\" stands for " + rule.none_means);
  // Characters, not bytes: a UTF-8 name counts each of its letters once.
  std::size_t chars = 0;
  for (unsigned char c : trimmed) chars += (c & 0xC0) != 0x80;
  if (chars > rule.max_chars)
    throw InputError(field, rule.what + " has at most " + std::to_string(rule.max_chars) +
                                " characters (\"" + trimmed.substr(0, 20) + "…\" has " +
                                std::to_string(chars) + ")");
  return trimmed;
}

}  // namespace rockface::storage
