#pragma once
// The densely mapped face (tests/support/dense_face.h) as the tablet stores
// it: one visit with the face's area, each trace as a trace measurement and
// its own joint plane measured from it; shared by the dense-visit tests and
// the Mapping screen's benchmark.
#include <cstddef>
#include <filesystem>

#include "storage/project/project_store.h"
#include "tests/support/dense_face.h"

namespace rockface::test {

// The face's outline, measured as an area (the free surface).
inline storage::Measurement face_area(const DenseFace& face) {
  storage::Measurement area;
  area.kind = storage::Measurement::Kind::area;
  area.label = "FACE";
  area.points = face.polygon();
  area.dip_deg = 90;
  area.dipdir_deg = 180;
  area.rock_side = "lower";
  return area;
}

inline storage::Measurement trace_measurement(const DenseFaceTrace& t) {
  storage::Measurement m;
  m.kind = storage::Measurement::Kind::trace;
  m.label = t.id;
  m.joint_label = t.joint;
  m.points = {t.from, t.point, t.to};
  m.dip_deg = t.dip;
  m.dipdir_deg = t.dipdir;
  return m;
}

inline storage::Joint joint_of(const DenseFaceTrace& t) {
  storage::Joint j;
  j.label = t.joint;
  j.dip_deg = t.dip;
  j.dipdir_deg = t.dipdir;
  j.point = t.point;
  j.friction_deg = t.friction;
  j.cohesion_pa = 0;
  j.source = "trace " + t.id;
  j.type = "trace";
  return j;
}

// A new project at `file` with one visit: the face's area, the joints of
// every trace, and the first `traces` trace measurements (the rest are
// stored one by one later by a test that maps trace by trace).
inline storage::RecordId make_dense_visit(const std::filesystem::path& file, const DenseFace& face,
                                          std::size_t traces) {
  storage::ProjectInfo info;
  info.name = "face mapped trace by trace";
  info.datum = {2690000.0, 1170000.0, 1100.0};
  storage::ProjectStore store = storage::ProjectStore::create(file, info);
  const storage::RecordId visit = store.begin_visit("tablet");
  std::vector<storage::Measurement> measurements{face_area(face)};
  std::vector<storage::Joint> joints;
  for (const auto& t : face.traces) joints.push_back(joint_of(t));
  for (std::size_t k = 0; k < traces && k < face.traces.size(); ++k)
    measurements.push_back(trace_measurement(face.traces[k]));
  store.save_measurements(visit, measurements);
  store.save_joints(visit, {}, joints);
  return visit;
}

}  // namespace rockface::test
