#include "core/measure/pick_measurement.h"

#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/measure/joined_traces.h"
#include "core/measure/least_cost_trace.h"
#include "core/measure/no_surface_cause.h"
#include "core/measure/pair_photo.h"
#include "core/measure/tolerances.h"

namespace rockface::measure {

namespace {

const PhotoView& view_of(const MeasureContext& c, const std::string& photo,
                         const std::string& where) {
  const auto it = c.views.find(photo);
  if (it == c.views.end())
    throw InputError(where + ".photo", "the " + photo +
                                           " photograph's pose is not known for this model "
                                           "(a model file knows only the left one)");
  return it->second;
}

// The 3D image a photograph's picks land on: its pair's.
const MeshPicker& picker_of(const MeasureContext& c, const std::string& photo) {
  const auto own = c.pickers.find(photo);
  return own != c.pickers.end() ? *own->second : *c.picker;
}

void require_in_image(const PhotoView& view, const std::vector<Eigen::Vector2d>& pixels,
                      const std::string& where) {
  for (std::size_t i = 0; i < pixels.size(); ++i)
    if (!pixel_in_image(view, pixels[i])) {
      std::ostringstream s;
      s << "pixel (" << pixels[i].x() << ", " << pixels[i].y() << ") is outside the " << view.name
        << " photograph (" << view.camera.width << " x " << view.camera.height << ")";
      throw InputError(where + "[" + std::to_string(i) + "]", s.str());
    }
}

// The same rule as pixel_in_image, for a photograph of width x height px.
void require_in_photograph(const std::string& photo, int width, int height,
                           const std::vector<Eigen::Vector2d>& pixels, const std::string& where) {
  PhotoView view;
  view.name = photo;
  view.camera.width = width;
  view.camera.height = height;
  require_in_image(view, pixels, where);
}

// Every tap with surface under it; one without says why, from the
// photograph it was tapped on (issue 39: "no surface" alone on a face too
// dark to match).
void require_surface(const MeasureContext& c, const MeshPicker& picker, const PhotoView& view,
                     const std::string& photo, const std::vector<Eigen::Vector2d>& pixels,
                     const std::function<std::string(std::size_t)>& where_of) {
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    if (picker.pick(view, pixels[i], where_of(i))) continue;
    const auto it = c.photos.find(photo);
    throw InputError(
        where_of(i),
        "no surface of the 3D image under this pick: " +
            no_surface_cause(it == c.photos.end() ? cv::Mat() : it->second, photo, pixels[i]));
  }
}

}  // namespace

void check_picks_in_photographs(const Picks& picks, int width, int height,
                                const std::string& source) {
  const std::string prefix = source.empty() ? std::string() : source + ": ";
  for (const auto& t : picks.traces) {
    const std::string where = prefix + t.where;
    if (!t.pixels.empty())
      require_in_photograph(pair_photo(t.pair, t.photo), width, height, t.pixels,
                            where + ".pixels");
    if (t.ends) {
      require_in_photograph(pair_photo(t.pair, t.photo), width, height,
                            {(*t.ends)[0], (*t.ends)[1]}, where + ".ends");
      if (t.cost == "curvature" && t.photo != "left")
        throw InputError(where + ".cost",
                         "the curvature cost follows the 3D image on the left photograph only");
    }
  }
  for (const auto& a : picks.areas)
    require_in_photograph(pair_photo(a.pair, a.photo), width, height, a.polygon,
                          prefix + a.where + ".polygon");
  for (const auto& p : picks.points)
    require_in_photograph(pair_photo(p.pair, p.photo), width, height, {p.pixel},
                          prefix + p.where + ".pixel");
}

const std::string& MeasuredPicks::pole_id(std::size_t k) const {
  const PoleSource& s = poles[k];
  switch (s.kind) {
    case 't':
      return traces[s.index].m.id;
    case 'a':
      return areas[s.index].m.id;
    case 'j':
      return joined[s.index].face.label;
    default:
      return points[s.index].id;
  }
}

const PlaneEstimate& MeasuredPicks::pole_plane(std::size_t k) const {
  const PoleSource& s = poles[k];
  switch (s.kind) {
    case 't':
      return traces[s.index].m.plane;
    case 'a':
      return areas[s.index].m.plane;
    case 'j':
      return joined[s.index].plane;
    default:
      return points[s.index].plane;
  }
}

std::string MeasuredPicks::set_of(const std::string& id) const {
  for (std::size_t k = 0; k < poles.size(); ++k)
    if (pole_id(k) == id) {
      const int set = clusters.set_of.empty() ? -1 : clusters.set_of[k];
      return set >= 0 && set < static_cast<int>(sets.size()) ? sets[set].label : std::string();
    }
  return {};
}

MeasuredPicks measure_picks(const Picks& picks, const MeasureContext& c,
                            std::optional<int> wanted_sets) {
  if (!c.picker) throw Error("measure_picks: no mesh");
  const std::string prefix = c.source.empty() ? std::string() : c.source + ": ";
  MeasuredPicks out;
  for (const auto& t : picks.traces) {
    const std::string where = prefix + t.where;
    MeasuredTrace mt;
    mt.joint = t.joint;
    mt.origin = t.origin;
    if (!t.points.empty()) {
      std::vector<Eigen::Vector3d> relative;
      for (const auto& p : t.points) relative.push_back(p - c.datum);
      // A further pair's trace given by its points (a visit's stored trace
      // measured again) lies on that pair's 3D image, as its taps would.
      const MeshPicker& on = t.pair > 1 ? picker_of(c, pair_photo(t.pair, "left")) : *c.picker;
      mt.m = measure_trace_points(on, t.id, relative, c.settings, where);
    } else if (!t.pixels.empty()) {
      const PhotoView& view = view_of(c, t.photo, where);
      require_in_image(view, t.pixels, where + ".pixels");
      mt.taps = t.pixels;
      require_surface(c, picker_of(c, t.photo), view, t.photo, t.pixels,
                      [&](std::size_t i) { return where + ".pixels[" + std::to_string(i) + "]"; });
      mt.m = measure_trace(picker_of(c, t.photo), view, t.id, t.pixels, c.settings, where);
    } else {
      const PhotoView& view = view_of(c, t.photo, where);
      const std::vector<Eigen::Vector2d> ends{(*t.ends)[0], (*t.ends)[1]};
      require_in_image(view, ends, where + ".ends");
      const auto photo = c.photos.find(t.photo);
      if (photo == c.photos.end() || photo->second.empty())
        throw InputError(where + ".ends", "semi-automatic tracing needs the " + t.photo +
                                              " photograph, which this model does not have");
      TraceRequest request;
      request.from = ends[0];
      request.to = ends[1];
      request.cost = trace_cost_by_name(t.cost, where + ".cost");
      if (request.cost == TraceCost::Curvature && t.photo != "left")
        throw InputError(where + ".cost",
                         "the curvature cost follows the 3D image on the left photograph only");
      require_surface(c, *c.picker, view, t.photo, ends,
                      [&](std::size_t k) { return where + ".ends[" + std::to_string(k) + "]"; });
      const TracedPath path =
          trace_between(photo->second, &c.picker->mesh(), request, where + ".ends");
      // The path may cross small holes of the 3D image (a dark trace is
      // where dense matching fails first): the fit uses the pixels with
      // surface under them.
      std::vector<Eigen::Vector2d> on_surface;
      for (const auto& px : path.pixels)
        if (c.picker->pick(view, px, where)) on_surface.push_back(px);
      mt.taps = ends;
      mt.cost = t.cost;
      mt.mean_cost = path.mean_cost;
      mt.m = measure_trace(*c.picker, view, t.id, on_surface, c.settings, where);
    }
    // A compass reading gives the plane (and says how the trace lies in it).
    if (t.compass) mt.compass = apply_compass_reading(mt.m, *t.compass, where + ".compass");
    out.traces.push_back(std::move(mt));
  }
  for (const auto& a : picks.areas) {
    const std::string where = prefix + a.where;
    const PhotoView& view = view_of(c, a.photo, where);
    require_in_image(view, a.polygon, where + ".polygon");
    MeasuredArea area;
    area.m = measure_area(picker_of(c, a.photo), view, a.id, a.polygon, c.settings, where);
    // The side the rock is on comes from where the camera stood, never from
    // the order the corners were tapped in (free_face_side.h).
    if (a.rock_side.empty()) {
      area.sight = wind_toward_camera(area.m, view);
    } else {
      const FreeFaceSide side = free_face_side(area.m, view, a.rock_side, where);
      area.rock_side = side.rock_side;
      area.rock_side_from = side.from;
      area.marginal = side.marginal;
      area.sight = side.sight;
    }
    out.areas.push_back(std::move(area));
  }
  for (const auto& p : picks.points) {
    const std::string where = prefix + p.where;
    const PhotoView& view = view_of(c, p.photo, where);
    require_in_image(view, {p.pixel}, where + ".pixel");
    require_surface(c, picker_of(c, p.photo), view, p.photo, {p.pixel},
                    [&](std::size_t) { return where + ".pixel"; });
    out.points.push_back(
        measure_point(picker_of(c, p.photo), view, p.id, p.pixel, p.radius, c.settings, where));
  }

  // Joints marked piece by piece: their traces' points fitted together.
  std::map<std::string, std::size_t> joint_index;
  for (const auto& t : out.traces) {
    if (t.joint.empty()) continue;
    auto [it, added] = joint_index.emplace(t.joint, out.joints.size());
    if (added) out.joints.push_back({t.joint, {}, {}});
    out.joints[it->second].traces.push_back(t.m.id);
  }
  for (auto& j : out.joints) {
    std::vector<Eigen::Vector3d> points, normals;
    for (const auto& t : out.traces)
      if (t.joint == j.label) {
        points.insert(points.end(), t.m.points.begin(), t.m.points.end());
        normals.insert(normals.end(), t.m.surface_normals.begin(), t.m.surface_normals.end());
      }
    if (normals.size() != points.size()) normals.clear();
    j.plane = fit_trace_plane(points, normals, c.settings);
    // Readings of the joint itself win over its traces' points (issue 27),
    // as they do for a trace: a joint marked by straight traces on a flat
    // face has no plane of its own, and a geologist who held a compass on
    // it has one. Several readings: their mean normal (each upward), the
    // compass's sigma; the points still place the plane (their centroid).
    Eigen::Vector3d read_normal = Eigen::Vector3d::Zero();
    std::vector<std::string> read_by;
    for (const auto& t : out.traces)
      if (t.joint == j.label && t.compass) {
        read_normal += t.m.plane.fit.normal;
        read_by.push_back(t.m.id);
      }
    if (!read_by.empty()) {
      const bool fitted = j.plane.known;
      const Eigen::Vector3d fitted_normal = j.plane.fit.normal;
      j.plane.known = true;
      j.plane.fit.normal = read_normal.normalized();
      j.plane.orientation = geometry::plane_orientation(j.plane.fit.normal);
      j.plane.sigma = deg_to_rad(kCompassSigmaDeg);
      std::string by;
      for (const auto& id : read_by) by += (by.empty() ? "" : ", ") + id;
      j.plane.problem = "orientation from the compass reading of " + by;
      if (fitted) {
        const double apart =
            rad_to_deg(std::acos(std::min(1.0, std::abs(fitted_normal.dot(j.plane.fit.normal)))));
        j.plane.problem +=
            "; the plane fitted to its traces is " + format_fixed(apart, 1, " deg") + " from it";
      }
    }
  }

  // Pieces of one trace tapped in different pairs' photographs are one
  // trace (the same rule as the replay's and the tablet's): one pole, one
  // trace length, in the statistics below.
  out.joined = joined_traces(photogrammetry::join_trace_pieces(trace_pieces(out)), out, c.settings);
  std::set<std::string> in_joined;
  for (const auto& j : out.joined) in_joined.insert(j.face.pieces.begin(), j.face.pieces.end());

  // Joint sets over the discontinuities whose plane is known.
  std::vector<Eigen::Vector3d> poles;
  std::vector<SetMember> members;
  for (std::size_t i = 0; i < out.traces.size(); ++i) {
    const auto& m = out.traces[i].m;
    if (!m.plane.known || in_joined.count(m.id)) continue;
    out.poles.push_back({'t', i});
    poles.push_back(m.plane.fit.normal);
    members.push_back({m.plane.fit.normal, m.plane.fit.centroid, m.length, m.censored});
  }
  for (std::size_t i = 0; i < out.joined.size(); ++i) {
    const auto& j = out.joined[i];
    if (!j.plane.known) continue;
    out.poles.push_back({'j', i});
    poles.push_back(j.plane.fit.normal);
    members.push_back({j.plane.fit.normal, j.plane.fit.centroid, j.length, j.censored});
  }
  for (std::size_t i = 0; i < out.areas.size(); ++i) {
    const auto& a = out.areas[i];
    if (!a.m.plane.known || !a.rock_side.empty()) continue;  // a free face is no joint
    out.poles.push_back({'a', i});
    poles.push_back(a.m.plane.fit.normal);
    members.push_back({a.m.plane.fit.normal, a.m.plane.fit.centroid, std::nullopt, false});
  }
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    const auto& p = out.points[i];
    if (!p.plane.known) continue;
    out.poles.push_back({'p', i});
    poles.push_back(p.plane.fit.normal);
    members.push_back({p.plane.fit.normal, p.point, std::nullopt, false});
  }
  if (!poles.empty()) {
    ClusterOptions options;
    options.count = wanted_sets.value_or(0);
    if (options.count > static_cast<int>(poles.size()))
      throw InputError(prefix + "sets", "asks for " + std::to_string(options.count) +
                                            " sets but only " + std::to_string(poles.size()) +
                                            " planes are known");
    out.clusters = cluster_poles(poles, options);
    out.sets = summarise_joint_sets(members, out.clusters);
  }
  return out;
}

}  // namespace rockface::measure
