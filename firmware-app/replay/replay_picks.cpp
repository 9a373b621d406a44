#include "firmware-app/replay/replay_picks.h"

#include <deque>
#include <map>
#include <set>

#include "core/common/error.h"
#include "core/common/units.h"
#include "core/measure/joined_traces.h"
#include "core/measure/mesh_picker.h"
#include "core/measure/pair_photo.h"

namespace rockface::app {

namespace {

void check_pair(const storage::Scene& scene, const std::string& where, int pair,
                std::size_t pairs) {
  if (static_cast<std::size_t>(pair) > pairs)
    throw InputError(scene.source + ": " + where + ".pair",
                     "pair " + std::to_string(pair) + ", but imaging.stations gives " +
                         std::to_string(pairs) + (pairs == 1 ? " pair" : " pairs"));
}

}  // namespace

void check_pick_pairs(const storage::Scene& scene, std::size_t pairs) {
  if (!scene.picks) return;
  for (const auto& t : scene.picks->traces) check_pair(scene, t.where, t.pair, pairs);
  for (const auto& a : scene.picks->areas) check_pair(scene, a.where, a.pair, pairs);
  for (const auto& p : scene.picks->points) check_pair(scene, p.where, p.pair, pairs);
}

void check_picks_before_capture(const storage::Scene& scene, std::size_t pairs) {
  if (!scene.picks) return;
  check_pick_pairs(scene, pairs);
  if (scene.imaging)
    measure::check_picks_in_photographs(*scene.picks, scene.imaging->camera.width,
                                        scene.imaging->camera.height, scene.source);
}

ReplayPicks measure_replay_picks(const storage::Scene& scene,
                                 const photogrammetry::ReconstructionResult& rec,
                                 const photogrammetry::CameraIntrinsics& intrinsics,
                                 const photogrammetry::ReconstructionPreset& preset,
                                 const cv::Mat& left_image, const cv::Mat& right_image,
                                 const MorePairsOutcome* more) {
  check_pick_pairs(scene, more ? more->images.size() : 1);
  const measure::MeshPicker picker(rec.mesh);
  measure::MeasureContext c;
  c.picker = &picker;
  c.views.emplace("left", measure::left_view(rec.model_to_world, intrinsics));
  c.views.emplace("right", measure::right_view(rec.model_to_world, rec.orientation.R,
                                               rec.orientation.t, intrinsics));
  c.photos["left"] = left_image;
  c.photos["right"] = right_image;
  c.settings.point_sigma = rec.accuracy.sigma_z;
  // Neighbouring points share the dense-matching window: one independent
  // point per window on the surface.
  c.settings.correlation_length = rec.point_spacing * preset.sgbm_block_size;
  c.datum = scene.datum;
  c.source = scene.source;

  // A further pair's taps: its left photograph, its 3D image moved into the
  // face frame (the first pair's), so every measurement lands in that frame.
  const measure::Picks picks = measure::picks_by_pair_photo(*scene.picks);
  std::deque<photogrammetry::SurfaceMesh> face_meshes;  // the pickers refer to them
  std::deque<measure::MeshPicker> further_pickers;
  std::set<int> pairs;
  for (const auto& t : picks.traces) pairs.insert(t.pair);
  for (const auto& a : picks.areas) pairs.insert(a.pair);
  for (const auto& p : picks.points) pairs.insert(p.pair);
  for (const int pair : pairs) {
    if (pair == 1) continue;
    const std::string photo = measure::pair_photo(pair, "left");
    const std::size_t k = static_cast<std::size_t>(pair - 1);
    const photogrammetry::Similarity& to_face = more->face.images[k].to_face;
    face_meshes.push_back(more->images[k].mesh);
    face_meshes.back().transform(to_face.scale, to_face.R, to_face.t);
    further_pickers.emplace_back(face_meshes.back());
    c.pickers[photo] = &further_pickers.back();
    measure::PhotoView view = measure::left_view(more->model_to_image[k].then(to_face), intrinsics);
    view.name = photo;  // the measurements name the pair's photograph
    c.views.emplace(photo, std::move(view));
    c.photos[photo] = more->images[k].photograph;
  }

  ReplayPicks out;
  out.measured = measure::measure_picks(picks, c, scene.picks->sets);

  // Pieces of one trace in different pairs' photographs become one trace.
  if (more) {
    std::vector<photogrammetry::ImageTrace> pieces;
    for (const auto& t : picks.traces) {
      if (t.pixels.empty() || t.photo == "right") continue;
      pieces.push_back({t.id, t.joint, t.pair - 1, t.pixels});
    }
    out.joined = measure::joined_traces(
        photogrammetry::traces_in_face_frame(more->images, more->face, pieces), out.measured,
        c.settings);
    for (const auto& j : out.joined) out.notes.push_back(measure::joined_note(j));
  }
  std::map<std::string, const measure::JoinedTrace*> joined_by_piece;
  for (const auto& j : out.joined)
    for (const auto& id : j.face.pieces) joined_by_piece[id] = &j;

  out.joints = scene.joints;
  // The trace as the analysis sees it: the picks lifted onto the 3D image
  // (the taps, or the ends of a semi-automatic trace), a polyline with
  // few vertices, not the hundreds of noisy samples the plane was fitted to.
  // A joined trace once, as its first piece, with the points of all pieces.
  for (std::size_t i = 0; i < out.measured.traces.size(); ++i) {
    const measure::MeasuredTrace& t = out.measured.traces[i];
    const measure::TracePick& pick = picks.traces[i];
    analysis::SceneTrace st;
    st.id = t.m.id;
    if (!t.joint.empty()) st.joint = t.joint;
    if (const auto j = joined_by_piece.find(st.id); j != joined_by_piece.end()) {
      if (j->second->face.label != st.id) continue;
      for (const auto& p : j->second->face.points) st.points.push_back(p + scene.datum);
    } else if (!pick.points.empty()) {
      st.points = pick.points;
    } else {
      const measure::PhotoView& view = c.views.at(pick.photo);
      const auto own = c.pickers.find(pick.photo);
      const measure::MeshPicker& on = own != c.pickers.end() ? *own->second : picker;
      for (std::size_t k = 0; k < t.taps.size(); ++k)
        if (const auto hit = on.pick(view, t.taps[k], pick.where))
          st.points.push_back(hit->point + scene.datum);
    }
    out.traces.push_back(std::move(st));
  }
  for (const measure::MeasuredJoint& j : out.measured.joints) {
    for (auto& sj : out.joints) {
      if (sj.id != j.label) continue;
      if (!j.plane.known) {
        out.notes.push_back(j.label + ": " + j.plane.problem +
                            "; the analysis keeps the scene's orientation for it");
        continue;
      }
      sj.dip = rad_to_deg(j.plane.orientation.dip);
      sj.dipdir = rad_to_deg(j.plane.orientation.dipdir);
      sj.point = j.plane.fit.centroid + scene.datum;
    }
  }
  return out;
}

}  // namespace rockface::app
