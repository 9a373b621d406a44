#pragma once
// The rounds along the drive for the office's drive page (issues 44 and 46:
// "the class per round against the chainage, next to RMR / Q and over /
// underbreak"): per placed visit of a pulled copy of the tunnel, by
// chainage, its RMR89 and Q with their classes, the support class the
// designer's classes propose and the one decided (who, when) — the same
// reading as `rockface drive --support-csv` (firmware-app/support/
// support_drive.h) — and the round's over- and underbreak against the
// design profile (firmware-app/tunnel/visit_profile.h). Every figure as
// text with its unit; the numbers a drawing needs beside it.
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "storage/project/project_store.h"

namespace rockface::app::office_web {

// `visit_uuid` names a visit of the pulled copy as the server does (the
// page links to the visit); "" leaves the round without a link.
nlohmann::json rounds_page(storage::ProjectStore& store,
                           const std::function<std::string(storage::RecordId)>& visit_uuid);

}  // namespace rockface::app::office_web
