#pragma once
// `rockface support`'s output: the visit's support as JSON (format
// "rockface-support/1") and as lines for the terminal. Every figure is
// printed with its unit through core/common/number_format.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "firmware-app/support/visit_support.h"

namespace rockface::app {

nlohmann::json support_json(const VisitSupport& support);
std::vector<std::string> support_summary(const VisitSupport& support);

// The Q chart's proposal in words ("category 4, Sfr 6-9 cm + B: bolts
// 3.50 m at 2.19 m (shotcreted area)"), and Bieniawski's row.
std::string q_support_words(const rockmass::QSupport& q);
std::string rmr_support_words(const rockmass::RmrSupport& r);

}  // namespace rockface::app
