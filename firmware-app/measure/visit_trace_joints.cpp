#include "firmware-app/measure/visit_trace_joints.h"

#include "core/common/error.h"
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
  return pick;
}

}  // namespace

TraceJointTable trace_joint_table(const std::vector<storage::Measurement>& measurements,
                                  const measure::MeshPicker& picker,
                                  const measure::MeasureSettings& settings,
                                  storage::RecordId visit_id) {
  TraceJointTable out;
  measure::Picks picks;
  for (const auto& m : measurements) {
    if (m.kind != storage::Measurement::Kind::trace) continue;
    const measure::TracePick pick = trace_pick(m);
    // measure_picks stops at the first bad pick; a stored trace it cannot
    // measure (fewer than two points) gives no joint and is named instead.
    try {
      measure::measure_trace_points(picker, pick.id, pick.points, settings, pick.where);
    } catch (const InputError& e) {
      out.without_joint.push_back(m.label + ": " + e.what());
      continue;
    }
    picks.traces.push_back(pick);
  }
  if (picks.traces.empty()) return out;
  measure::MeasureContext context;
  context.picker = &picker;
  context.settings = settings;
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
