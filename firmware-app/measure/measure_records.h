#pragma once
// The measured picks (core/measure/pick_measurement.h) as project records:
// the measurements, the joint table and the joint sets of a visit. Shared by
// `rockface measure` on a project and `rockface replay`.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/measure/pick_measurement.h"
#include "storage/project/project_records.h"

namespace rockface::app {

// The model and capture of one pair of the visit: what a measurement taken
// in its photograph is stored with.
struct PairRecords {
  std::optional<storage::RecordId> model_id, capture_id;
};

// The measurements as project records (datum-relative points, the photo and
// pixels they came from; points only with a known plane) and the joint table: one joint per known
// plane of a trace, area or point, with its set, and the sets. Each
// measurement carries the model and capture of its photograph's pair:
// `first` for "left" / "right" and for 3D points, `further` by photograph
// name (measure::pair_photo) for a further pair's.
std::vector<storage::Measurement> measurement_records(
    const measure::MeasuredPicks& measured, storage::RecordId visit_id, const PairRecords& first,
    const std::map<std::string, PairRecords>& further = {});
std::vector<storage::JointSet> joint_set_records(const measure::MeasuredPicks& measured);
std::vector<storage::Joint> joint_records(const measure::MeasuredPicks& measured,
                                          storage::RecordId visit_id);

// The joints the traces name (`"joint": "J1"` on one or more traces),
// each fitted to all its traces' points (measure_picks: MeasuredPicks::
// joints), added to `joints` as `rockface replay` stores them: label "J1",
// type "trace", source "traces T1 T2", its point the fit's centroid, its
// set the one all its traces are in. Each replaces the one-trace joints of
// its traces (the tablet keeps such a joint as the geologist's and makes
// none of its traces). A named joint whose traces give no plane is not
// stored: its traces keep their own joints (unname_joints_without_plane,
// named_joint_notes say why).
// Throws InputError when a named joint's label is also a measurement's id
// (two joints of one label).
void add_named_joints(const measure::MeasuredPicks& measured, storage::RecordId visit_id,
                      std::vector<storage::Joint>& joints);
// The trace records of a named joint that is not stored (its traces give
// no plane) name it no more, so that the visit's traces name only joints
// it has (the analysis refuses a trace of an unknown joint): each says in
// its note which joint it was given and why that joint has no plane.
void unname_joints_without_plane(const measure::MeasuredPicks& measured,
                                 std::vector<storage::Measurement>& records);
// Each named joint in words: "J1 (traces T1 T2): joint 60.2/199.8, sigma
// 0.4 deg" with its fit's note, or "J1 (traces T1 T2): no joint stored:
// orientation unknown: ...".
std::vector<std::string> named_joint_notes(const measure::MeasuredPicks& measured);

// The measurement records with each joined trace's pieces replaced by one
// trace record (the first piece's, with the joined points and plane).
void join_trace_records(const std::vector<measure::JoinedTrace>& joined,
                        std::vector<storage::Measurement>& records);
// The joint table likewise: a further piece's joint goes, the first piece's
// takes the joined plane (persistence: the joined length), or goes when
// that plane is unknown.
void join_trace_joints(const std::vector<measure::JoinedTrace>& joined,
                       std::vector<storage::Joint>& joints);

}  // namespace rockface::app
