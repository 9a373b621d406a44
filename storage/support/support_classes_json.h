#pragma once
// The designer's support classes as a file (format
// "rockface-support-classes/1", docs in storage/support/README.md) and as the
// text the project stores per tunnel and the office receives; the round's
// support decision as the text stored with a visit.
//
// The reader refuses, naming the file and the field and the classes by
// name: an unknown key, a value out of its range (the bolt ranges of
// core/tunnel/support_ranges.h), two classes of one name, a class without
// an RMR (or Q) range while others give one, and RMR or Q ranges that
// overlap or leave a gap between neighbouring classes. Classes are listed
// from the lightest support to the heaviest, so their RMR and Q ranges
// descend.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "core/analysis/support_classes.h"
#include "core/analysis/support_decision.h"

namespace rockface::storage {

inline constexpr const char* kSupportClassesFormat = "rockface-support-classes/1";

analysis::SupportClasses parse_support_classes(const std::string& text, const std::string& source);
analysis::SupportClasses load_support_classes(const std::filesystem::path& file);
nlohmann::json support_classes_json(const analysis::SupportClasses& classes);

nlohmann::json support_decision_json(const analysis::SupportDecision& decision);
analysis::SupportDecision parse_support_decision(const std::string& text,
                                                 const std::string& source);

}  // namespace rockface::storage
