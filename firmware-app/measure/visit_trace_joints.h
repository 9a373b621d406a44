#pragma once
// The joint table of a visit's stored traces, as `rockface measure` makes it
// (issue 27: the tablet's Mapping screen stores traces one at a time): every
// trace taken as a pick given by its 3D points, measured by
// measure::measure_picks, then joint_records / join_trace_joints /
// joint_set_records (measure_records.h): one joint per trace whose plane is
// known, with its set when the traces make sets. The same code as the verb,
// so a trace stored from the tablet gives the joint the verb gives it.
#include <map>
#include <string>
#include <vector>

#include "core/measure/mesh_picker.h"
#include "core/measure/plane_measurement.h"
#include "storage/project/project_records.h"

namespace rockface::app {

struct TraceJointTable {
  std::vector<storage::Joint> joints;  // measurement_id: the trace's record
  std::vector<storage::JointSet> sets;
  // Each trace that gives no joint, in words ("T3: orientation unknown: the
  // trace is straight ..."): its plane unknown, or its points not a trace.
  std::vector<std::string> without_joint;
};

// `measurements`: the visit's (anything but traces is ignored), points
// relative to the project datum as stored; `picker`: the 3D image the
// traces lie on (the normals along each trace, for the relief test). In a
// visit of several pairs each trace lies on its own pair's 3D image:
// `pickers` by model id; a trace whose record's model is not there is
// measured on `picker`.
TraceJointTable trace_joint_table(
    const std::vector<storage::Measurement>& measurements, const measure::MeshPicker& picker,
    const measure::MeasureSettings& settings, storage::RecordId visit_id,
    const std::map<storage::RecordId, const measure::MeshPicker*>& pickers = {});

// A trace record as `rockface measure` stores it (measurement_records): the
// trace measured from its 3D points on `picker`, its plane, sigma, length
// and note; the photograph, its pixels and model as given in `tapped`; its
// plane the compass reading of `tapped` where it has one (issue 27).
storage::Measurement measured_trace_record(const storage::Measurement& tapped,
                                           const measure::MeshPicker& picker,
                                           const measure::MeasureSettings& settings);

}  // namespace rockface::app
