#include "firmware-app/measure/visit_trace_joints.h"

#include "core/common/error.h"
#include "core/measure/pair_photo.h"
#include "core/measure/pick_measurement.h"
#include "firmware-app/measure/measure_records.h"

namespace rockface::app {

namespace {

measure::TracePick trace_pick(const storage::Measurement& m) {
  measure::TracePick pick;
  pick.id = m.label;
  pick.joint = m.joint_label;
  pick.where = "trace " + m.label;
  pick.points = m.points;  // the context's datum is zero: stored points stay as they are
  pick.origin = m.origin;
  if (m.compass_dip_deg && m.compass_dipdir_deg)  // issue 27: its plane is the reading
    pick.compass = measure::CompassReading{*m.compass_dip_deg, *m.compass_dipdir_deg};
  return pick;
}

}  // namespace

TraceJointTable trace_joint_table(
    const std::vector<storage::Measurement>& measurements, const measure::MeshPicker& picker,
    const measure::MeasureSettings& settings, storage::RecordId visit_id,
    const std::map<storage::RecordId, const measure::MeshPicker*>& pickers) {
  TraceJointTable out;
  measure::Picks picks;
  measure::MeasureContext context;
  context.picker = &picker;
  context.settings = settings;
  // Each further pair's 3D image as measure_picks names it ("pair 2 left"):
  // a trace given by its points is measured on its pair's (issue 27).
  std::map<storage::RecordId, int> pair_of_model;
  for (const auto& [model, on] : pickers)
    if (on && on != &picker) {
      const int pair = static_cast<int>(pair_of_model.size()) + 2;
      pair_of_model[model] = pair;
      context.pickers[measure::pair_photo(pair, "left")] = on;
    }
  for (const auto& m : measurements) {
    if (m.kind != storage::Measurement::Kind::trace) continue;
    measure::TracePick pick = trace_pick(m);
    if (m.model_id)
      if (const auto p = pair_of_model.find(*m.model_id); p != pair_of_model.end())
        pick.pair = p->second;
    const measure::MeshPicker& on =
        pick.pair > 1 ? *context.pickers.at(measure::pair_photo(pick.pair, "left")) : picker;
    // measure_picks stops at the first bad pick; a stored trace it cannot
    // measure (fewer than two points) gives no joint and is named instead.
    try {
      measure::measure_trace_points(on, pick.id, pick.points, settings, pick.where);
    } catch (const InputError& e) {
      out.without_joint.push_back(m.label + ": " + e.what());
      continue;
    }
    picks.traces.push_back(pick);
  }
  if (picks.traces.empty()) return out;
  const measure::MeasuredPicks measured = measure::measure_picks(picks, context, std::nullopt);
  out.joints = joint_records(measured, visit_id);
  join_trace_joints(measured.joined, out.joints);
  out.sets = joint_set_records(measured);
  for (auto& j : out.joints)
    for (const auto& m : measurements)
      if (m.kind == storage::Measurement::Kind::trace && m.label == j.label && m.id)
        j.measurement_id = m.id;
  for (const auto& t : measured.traces)
    if (!t.m.plane.known) out.without_joint.push_back(t.m.id + ": " + t.m.plane.problem);
  return out;
}

storage::Measurement measured_trace_record(const storage::Measurement& tapped,
                                           const measure::MeshPicker& picker,
                                           const measure::MeasureSettings& settings) {
  measure::MeasuredPicks one;
  measure::MeasuredTrace t;
  t.m = measure::measure_trace_points(picker, tapped.label, tapped.points, settings,
                                      "trace " + tapped.label);
  t.joint = tapped.joint_label;
  t.origin = tapped.origin;
  if (tapped.compass_dip_deg && tapped.compass_dipdir_deg)
    t.compass =
        measure::apply_compass_reading(t.m, {*tapped.compass_dip_deg, *tapped.compass_dipdir_deg},
                                       "trace " + tapped.label + ".compass");
  one.traces.push_back(std::move(t));
  storage::Measurement record =
      measurement_records(one, tapped.visit_id, {tapped.model_id, tapped.photo_capture_id}).front();
  // Where the taps were (measurement_records takes them from the picks,
  // which a trace given by its points has not).
  record.photo = tapped.photo;
  record.photo_capture_id = tapped.photo_capture_id;
  record.pixels = tapped.pixels;
  return record;
}

}  // namespace rockface::app
