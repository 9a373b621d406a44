#include "core/measure/joined_traces.h"

#include <limits>
#include <map>
#include <set>

#include "core/measure/pair_photo.h"

namespace rockface::measure {

std::vector<photogrammetry::TracePiece> trace_pieces(const MeasuredPicks& measured) {
  std::vector<photogrammetry::TracePiece> out;
  for (const auto& t : measured.traces)
    out.push_back({t.m.id, t.joint,
                   pair_of_photo(t.m.picks.empty() ? std::string() : t.m.picks.front().photo),
                   t.m.points});
  return out;
}

std::vector<JoinedTrace> joined_traces(std::vector<photogrammetry::FaceTrace> faces,
                                       const MeasuredPicks& measured,
                                       const MeasureSettings& settings) {
  std::map<std::string, const MeasuredTrace*> by_id;
  for (const auto& t : measured.traces) by_id[t.m.id] = &t;
  std::vector<JoinedTrace> out;
  for (auto& face : faces) {
    // Pieces in one photograph are traces the geologist drew apart (as for
    // a visit of one pair); pieces in different pairs' photographs are the
    // one trace crossing from one image to the next.
    if (std::set<int>(face.images.begin(), face.images.end()).size() < 2) continue;
    JoinedTrace j;
    std::vector<Eigen::Vector3d> points, normals;
    for (const auto& id : face.pieces) {
      const TraceMeasurement& m = by_id.at(id)->m;
      points.insert(points.end(), m.points.begin(), m.points.end());
      normals.insert(normals.end(), m.surface_normals.begin(), m.surface_normals.end());
    }
    if (normals.size() != points.size()) normals.clear();
    j.plane = fit_trace_plane(points, normals, settings);
    // Along the points in steps of the join distance: where the pieces
    // overlap their points interleave, differing across the run by the
    // registration residual (~1 cm), and summed point to point that
    // zigzag would lengthen the trace.
    const double step = photogrammetry::FaceTraceOptions{}.join_distance;
    Eigen::Vector3d last = face.points.front();
    for (std::size_t k = 1; k < face.points.size(); ++k)
      if (const double d = (face.points[k] - last).norm();
          d >= step || k + 1 == face.points.size()) {
        j.length += d;
        last = face.points[k];
      }
    // Each end of the joined trace is some piece's end: censored as that
    // end is (the piece ends where pieces meet are inside the trace).
    for (const Eigen::Vector3d& end : {face.points.front(), face.points.back()}) {
      double nearest = std::numeric_limits<double>::infinity();
      bool censored = false;
      for (const auto& id : face.pieces) {
        const TraceMeasurement& m = by_id.at(id)->m;
        if (m.points.empty()) continue;
        for (const int e : {0, 1})
          if (const double d = ((e == 0 ? m.points.front() : m.points.back()) - end).norm();
              d < nearest) {
            nearest = d;
            censored = m.censored_ends[e];
          }
      }
      j.censored = j.censored || censored;
    }
    j.face = std::move(face);
    out.push_back(std::move(j));
  }
  return out;
}

std::string joined_note(const JoinedTrace& joined) {
  std::string list;
  for (const auto& id : joined.face.pieces) list += (list.empty() ? "" : ", ") + id;
  return joined.face.label + ": one trace across the pairs' photographs (" + list + ")";
}

}  // namespace rockface::measure
