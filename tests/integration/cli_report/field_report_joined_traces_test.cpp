// The field report of a visit whose joint trace was marked in two pieces on
// two pairs' 3D images (issue 28): the pieces are drawn as one trace, and
// the joint sets are clustered with the joined trace counted once.
#include <gtest/gtest.h>

#include "core/geometry/orientation.h"
#include "storage/field_report/field_report.h"
#include "storage/project/project_store.h"
#include "tests/support/sample_records.h"

namespace {

using namespace rockface::storage;

TEST(FieldReportJoinedTraces, PiecesAreOneTraceAndOnePole) {
  test::TempDir dir("field-report-joined");
  ProjectStore store = ProjectStore::create(dir / "site.rockface", test::sample_project());
  const RecordId visit = store.begin_visit("tablet");
  const RecordId m1 =
      store.save_model(test::sample_model(store.save_capture(test::sample_capture(visit, 1))));
  const RecordId m2 =
      store.save_model(test::sample_model(store.save_capture(test::sample_capture(visit, 2))));
  // T1 on pair 1 and T2 on pair 2 continue each other (1 cm apart where
  // they overlap, the registration's residual): one trace of J1. T5, 3 m
  // away, is another trace of J1; T3 and T4 are traces of J3. Each piece's
  // plane as measured: J1's about 60/200, J3's about 20/350.
  const Eigen::Vector3d run = Eigen::Vector3d(1, 0, -0.3).normalized();
  const Eigen::Vector3d across = Eigen::Vector3d(0.3, 0, 1).normalized();
  const Eigen::Vector3d start(0, 4, 2);
  auto trace = [&](const std::string& label, RecordId model, double from, double to, double offset,
                   double dip, double dipdir) {
    Measurement m;
    m.kind = Measurement::Kind::trace;
    m.model_id = model;
    m.label = label;
    m.joint_label = label == "T3" || label == "T4" ? "J3" : "J1";
    for (double s = from; s <= to + 1e-9; s += 0.1)
      m.points.push_back(start + s * run + offset * across);
    m.dip_deg = dip;
    m.dipdir_deg = dipdir;
    return m;
  };
  store.save_measurements(
      visit, {trace("T1", m1, 0.0, 1.2, 0, 59, 198), trace("T2", m2, 0.9, 2.0, 0.01, 61, 202),
              trace("T3", m1, 0.0, 1.0, 1.0, 20, 350), trace("T4", m1, 0.0, 1.0, 2.0, 21, 352),
              trace("T5", m1, 0.0, 1.0, 3.0, 60, 201)});

  const FieldReport r = collect_field_report(store, visit);
  ASSERT_EQ(r.traces.size(), 4u);
  EXPECT_EQ(r.traces[0].first, "T1+T2");
  // Both pieces' points in the one trace (13 + 12), from 0 to 2 m along it.
  EXPECT_EQ(r.traces[0].second.size(), 25u);
  EXPECT_EQ(r.traces[1].first, "T3");
  EXPECT_EQ(r.traces[2].first, "T4");
  EXPECT_EQ(r.traces[3].first, "T5");
  // Four poles: the joined trace once (the mean of 59/198 and 61/202,
  // within 0.1 degree of 60/200 as the two are symmetric about it), T3, T4,
  // T5.
  ASSERT_EQ(r.poles.size(), 4u);
  const Eigen::Vector3d j1 = rockface::geometry::plane_normal_deg(60, 200);
  int near_j1 = 0;
  for (const auto& p : r.poles)
    if (std::abs(p.dot(j1)) > std::cos(0.1 * M_PI / 180)) ++near_j1;
  EXPECT_EQ(near_j1, 1);
  // Two sets of two members each, clustered from four measured planes: J1's
  // joined trace counts once, not once per piece.
  ASSERT_EQ(r.sets.size(), 2u);
  for (const auto& s : r.sets) {
    EXPECT_EQ(s.count, 2) << s.label;
    EXPECT_EQ(s.origin, "clustered from 4 measured planes");
  }
}

}  // namespace
