#pragma once
// A short name a person types for a record (the geologist of a visit, the
// heading it was taken at): one line, trimmed of spaces, at most so many
// letters, and never the text the readers show for "none".
#include <cstddef>
#include <string>

namespace rockface::storage {

struct OneLineNameRule {
  std::string what;        // "a geologist's name": the refusals' subject
  std::string examples;    // "(\"Anna Berger\")": shown when a name is refused
  std::string none;        // what the readers show for no name ("not recorded")
  std::string none_means;  // "no geologist: give a name, or none"
  std::size_t max_chars = 0;
};

// The name as kept: trimmed of spaces; "" for none. InputError naming
// `field` for a control character (a line break, a tab), the readers' text
// for none, or more than rule.max_chars characters (a UTF-8 letter counts
// once).
std::string checked_one_line_name(const std::string& name, const OneLineNameRule& rule,
                                  const std::string& field);

}  // namespace rockface::storage
