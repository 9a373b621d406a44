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
#include <vector>

#include <nlohmann/json.hpp>

#include "firmware-app/tunnel/round_start.h"
#include "storage/project/project_store.h"

namespace rockface::app::office_web {

// One round's over- and underbreak as the rounds page shows it
// (excavation_text; overbreak_m3 and underbreak_m3 when measured) and what
// the figures rest on besides the visit's own records and the tunnel's,
// so that kept figures can be checked against the drive as it is later:
// where the round ends (round_to), its heading's drive direction (sense,
// +1 / -1), and the earlier face of its heading it was measured from
// (previous_face: its chainage, null when none; firmware-app/tunnel/
// round_start.h). Measured on the visit's 3D image: seconds on a real one.
// `drive`: the store's faces when every round of a drive is measured (read
// once); else read here.
nlohmann::json round_excavation(storage::ProjectStore& store, storage::RecordId visit,
                                const DriveFaces* drive = nullptr);

// Whether kept figures of round_excavation still hold on `drive` (the
// drive's stored faces now): the round's heading is read in the same
// direction and its earlier face is the one they were measured from. A
// visit of the heading placed since between that face and the round's end
// starts the round elsewhere.
bool kept_excavation_holds(const nlohmann::json& kept, const DriveFaces& drive,
                           storage::RecordId visit);

// `visit_uuid` names a visit of the pulled copy as the server does (the
// page links to the visit); "" leaves the round without a link.
// `excavation` gives a round's over- and underbreak (round_excavation's or
// kept figures).
nlohmann::json rounds_page(storage::ProjectStore& store,
                           const std::function<std::string(storage::RecordId)>& visit_uuid,
                           const std::function<nlohmann::json(storage::RecordId)>& excavation);
// Every round measured here.
nlohmann::json rounds_page(storage::ProjectStore& store,
                           const std::function<std::string(storage::RecordId)>& visit_uuid);

}  // namespace rockface::app::office_web
