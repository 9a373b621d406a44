#pragma once
// The measured picks (core/measure/pick_measurement.h) as project records:
// the measurements, the joint table and the joint sets of a visit. Shared by
// `rockface measure` on a project and `rockface replay`.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/measure/pick_measurement.h"
#include "storage/project_records.h"

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
