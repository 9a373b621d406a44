#include "storage/project/visit_geologist.h"

#include "storage/project/one_line_name.h"

namespace rockface::storage {

std::string checked_geologist(const std::string& name, const std::string& field) {
  static const OneLineNameRule rule{"a geologist's name", "(\"Anna Berger\")",
                                    kGeologistNotRecorded, "no geologist: give a name, or none",
                                    kGeologistMaxChars};
  return checked_one_line_name(name, rule, field);
}

}  // namespace rockface::storage
