#include "firmware-app/office/office_rounds.h"

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/rockmass/q_system.h"
#include "core/rockmass/rmr89.h"
#include "firmware-app/support/support_drive.h"
#include "firmware-app/tunnel/visit_profile.h"

namespace rockface::app::office_web {

using nlohmann::json;

json round_excavation(storage::ProjectStore& store, storage::RecordId visit,
                      const DriveFaces* drive) {
  json round;
  try {
    const VisitProfile p = visit_profile(store, visit, Preset::standard, drive);
    round["round_to"] = p.round_to;
    // The heading's drive direction, not the tunnel's (round_start.h).
    round["sense"] = p.sense;
    round["previous_face"] = p.previous_face ? json(*p.previous_face) : json(nullptr);
    const auto& d = p.deviation;
    using tunnel::DeviationStatus;
    if (d.status == DeviationStatus::no_walls_in_view) {
      // Unknown, never zero (issue 38).
      round["excavation_text"] = "unknown: the 3D image saw no wall or roof of the round";
    } else if (d.status == DeviationStatus::outside_alignment) {
      round["excavation_text"] = "unknown: the round lies off the tunnel's alignment";
    } else {
      // A round's volumes to 0.01 m³ (10 litres): a finer figure is
      // beyond the surface's depth precision over a round's area.
      round["overbreak_m3"] = d.overbreak_volume_m3;
      round["underbreak_m3"] = d.underbreak_volume_m3;
      round["excavation_text"] = "over " + format_fixed(d.overbreak_volume_m3, 2, " m³") +
                                 ", under " + format_fixed(d.underbreak_volume_m3, 2, " m³") +
                                 " (" + format_fixed(d.seen_fraction * 100, 0, " %") +
                                 " seen, ch " + format_fixed(p.round_from, 1, " m") + " to " +
                                 format_fixed(p.round_to, 1, " m") + ")";
    }
  } catch (const InputError& e) {
    // Nothing measured: no earlier face to check it against later (the
    // visit's own records decide it).
    round["excavation_text"] = std::string("not evaluated: ") + e.what();
  }
  return round;
}

bool kept_excavation_holds(const json& kept, const DriveFaces& drive, storage::RecordId visit) {
  if (!kept.contains("round_to")) return kept.contains("excavation_text");
  // The heading read the other way now (its visits since show it) or the
  // visit named to another heading: measured again.
  const double sense = drive.sense_of(drive.heading_of(visit));
  if (kept.at("sense").get<double>() != sense) return false;
  const auto previous = drive.previous_face(visit, kept.at("round_to").get<double>(), sense);
  const json& was = kept.at("previous_face");
  // The same stored chainage read back: exact equality.
  return previous ? was.is_number() && was.get<double>() == previous->chainage : was.is_null();
}

json rounds_page(storage::ProjectStore& store,
                 const std::function<std::string(storage::RecordId)>& visit_uuid,
                 const std::function<json(storage::RecordId)>& excavation) {
  json rounds = json::array();
  for (const RoundSupport& r : drive_support(store)) {
    json round;
    round["visit"] = visit_uuid(r.visit);
    round["chainage"] = r.chainage;
    // Chainage is surveyed to the centimetre.
    round["chainage_text"] = format_fixed(r.chainage, 2, " m");
    if (r.rmr) {
      round["rmr"] = *r.rmr;
      // RMR89 is a sum of whole-point ratings read off tables.
      round["rmr_text"] = format_fixed(*r.rmr, 0) + " (" +
                          rockmass::rmr_class_words(rockmass::rmr_class(*r.rmr)) + ")";
    } else {
      round["rmr_text"] = "open";
    }
    if (r.q) {
      round["q"] = *r.q;
      // Q spans six decades: three significant digits.
      round["q_text"] = format_significant(*r.q, 3) + " (" + rockmass::q_class_words(*r.q) + ")";
    } else {
      round["q_text"] = "open";
    }
    round["proposed"] = r.proposed.empty() ? "–" : r.proposed;
    round["decided"] = r.decided.empty() ? "not decided" : r.decided;
    round["decided_by"] = r.decided.empty() ? ""
                                            : "by " + r.decided_by +
                                                  (r.decided_at.empty() ? "" : ", " + r.decided_at);
    const json e = excavation(r.visit);
    for (const char* key : {"excavation_text", "overbreak_m3", "underbreak_m3"})
      if (e.contains(key)) round[key] = e.at(key);
    rounds.push_back(std::move(round));
  }
  json out;
  out["rounds"] = std::move(rounds);
  return out;
}

json rounds_page(storage::ProjectStore& store,
                 const std::function<std::string(storage::RecordId)>& visit_uuid) {
  const auto tunnel = store.load_tunnel();
  const DriveFaces drive = drive_faces(store, tunnel ? tunnel->drive : tunnel::Drive::ascending);
  return rounds_page(store, visit_uuid, [&](storage::RecordId visit) {
    return round_excavation(store, visit, &drive);
  });
}

}  // namespace rockface::app::office_web
