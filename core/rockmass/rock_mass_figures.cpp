#include "core/rockmass/rock_mass_figures.h"

#include <algorithm>
#include <cstdio>

namespace rockface::rockmass {

RockMassFigures rock_mass_figures(const RockMassInput& in) {
  validate(in.form);  // refuse a bad form before any work
  RockMassFigures out;
  out.form = in.form;
  std::vector<Eigen::Vector3d> outline = in.outline_points;
  if (outline.empty())
    for (const auto& t : in.traces) outline.insert(outline.end(), t.points.begin(), t.points.end());
  out.window = face_window(outline);
  out.assigned = assign_traces_to_sets(in.traces, in.sets, out.window);
  out.spacings = set_spacings(in.traces, in.sets, out.assigned, out.window);
  out.persistence = set_persistence(in.traces, in.sets, out.assigned);
  out.scanlines = scanline_rqd(in.traces, out.assigned, in.sets, out.spacings, out.window);
  out.jv = volumetric_joint_count(out.spacings, static_cast<int>(out.assigned.random.size()),
                                  out.window.area_m2);
  std::vector<Eigen::Vector3d> normals;
  for (const auto& s : in.sets) normals.push_back(s.normal);
  out.blocks = block_sizes(in.blocks, out.spacings, normals, out.jv.jv);
  out.sets = static_cast<int>(in.sets.size());
  out.random_joints = !out.assigned.random.empty();
  out.drive = in.drive;

  // What the figures give the sheets.
  MeasuredForRmr& mr = out.measured_rmr;
  mr.rqd_percent = out.scanlines.rqd_percent;
  for (const auto& s : out.spacings)
    if (s.mean_m && (!mr.spacing_m || *s.mean_m < *mr.spacing_m)) {
      mr.spacing_m = s.mean_m;
      mr.spacing_set = s.label;
    }
  // Table E rates the least favourable: the longest persistence estimated.
  for (const auto& p : out.persistence)
    if (p.persistence_m && (!mr.persistence_m || *p.persistence_m > *mr.persistence_m))
      mr.persistence_m = p.persistence_m;
  if (!in.drive.empty()) {
    const SetAgainstDrive* worst = &in.drive.front();
    for (const auto& d : in.drive)
      if (static_cast<int>(d.cls) > static_cast<int>(worst->cls)) worst = &d;
    mr.orientation = worst->cls;
    mr.orientation_words = worst->label + ": " + worst->words;
    if (worst->marginal) mr.orientation_words += " (marginal)";
  }
  MeasuredForQ& mq = out.measured_q;
  mq.rqd_percent = out.scanlines.rqd_percent;
  if (!in.sets.empty() || !in.traces.empty()) mq.sets = out.sets;
  mq.random_joints = out.random_joints;

  if (!out.form.span_m && in.tunnel_span_m) out.form.span_m = in.tunnel_span_m;
  out.rmr = rmr89(mr, out.form);
  out.q = q_system(mq, out.form);

  if (!out.rmr.adjusted.value)
    out.notes.push_back("RMR89 incomplete: " + std::to_string(out.rmr.adjusted.missing.size()) +
                        " line(s) not entered");
  if (!out.q.q)
    out.notes.push_back("Q incomplete: " + std::to_string(out.q.missing.size()) +
                        " factor(s) not entered");
  for (const auto& s : out.spacings)
    if (s.in_blind_zone)
      out.notes.push_back(s.label +
                          " lies nearly parallel to the face (Terzaghi blind zone): "
                          "its traces under-sample it");
  return out;
}

}  // namespace rockface::rockmass
