#include "firmware-app/replay_picks.h"

#include "core/common/units.h"
#include "core/measure/mesh_picker.h"

namespace rockface::app {

ReplayPicks measure_replay_picks(const storage::Scene& scene,
                                 const photogrammetry::ReconstructionResult& rec,
                                 const photogrammetry::CameraIntrinsics& intrinsics,
                                 const photogrammetry::ReconstructionPreset& preset,
                                 const cv::Mat& left_image, const cv::Mat& right_image) {
  const measure::MeshPicker picker(rec.mesh);
  MeasureContext c;
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

  ReplayPicks out;
  out.measured = measure_picks(*scene.picks, c, scene.picks->sets);
  out.analysed = scene;
  out.analysed.traces.clear();
  // The trace as the analysis sees it: the picks lifted onto the 3D image
  // (the taps, or the ends of a semi-automatic trace), a polyline with
  // few vertices, not the hundreds of noisy samples the plane was fitted to.
  for (std::size_t i = 0; i < out.measured.traces.size(); ++i) {
    const MeasuredTrace& t = out.measured.traces[i];
    const storage::TracePick& pick = scene.picks->traces[i];
    storage::SceneTrace st;
    st.id = t.m.id;
    if (!t.joint.empty()) st.joint = t.joint;
    if (!pick.points.empty()) {
      st.points = pick.points;
    } else {
      const measure::PhotoView& view = c.views.at(pick.photo);
      for (std::size_t k = 0; k < t.taps.size(); ++k)
        if (const auto hit = picker.pick(view, t.taps[k], pick.where))
          st.points.push_back(hit->point + scene.datum);
    }
    out.analysed.traces.push_back(std::move(st));
  }
  for (const MeasuredJoint& j : out.measured.joints) {
    for (auto& sj : out.analysed.joints) {
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
