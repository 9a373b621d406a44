#pragma once
// Blocks on the 3D image where they lie on the mapped face: a block's
// footprint on the free surface (its corners that lie on the surface
// patches, or its loop of traces on the surface), laid on the drawn surface.
// The part on the 3D image is tinted in the verdict's colour and outlined;
// where the footprint runs past the 3D image, the image's border inside it
// is drawn dashed ("open / unknown" in the legend): the block goes on where
// nothing was photographed, and nothing is drawn in the air beyond.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>
#include <Eigen/Core>

#include "storage/project/project_records.h"
#include "ui/view3d/overlay_drape.h"
#include "ui/view3d/overlay_scene.h"

namespace rockface::ui {

struct AppState;
struct BlockView;

// The free surface's patches as the analysis takes them: the visit's areas
// (storage/scene/export_scene_json.cpp), each with its fitted plane.
struct SurfacePatchPlane {
  std::vector<Eigen::Vector3d> polygon;
  Eigen::Vector3d point = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::UnitZ();
};
std::vector<SurfacePatchPlane> surface_patches(
    const std::vector<storage::Measurement>& measurements);

// A block's outline on the free surface, in order. `surface_loop`: the
// vertices are that loop already. Else the corners on a patch (or, without
// patches, on the drawn surface) around their convex hull seen along the
// drape direction. Empty when fewer than three corners are on the surface.
std::vector<Eigen::Vector3d> block_footprint(const std::vector<Eigen::Vector3d>& vertices,
                                             bool surface_loop,
                                             const std::vector<SurfacePatchPlane>& patches,
                                             const SurfaceDrape& drape);

struct BlockOnFace {
  std::vector<Eigen::Vector2d> footprint;           // drape plane
  std::vector<Eigen::Vector3d> fill;                // triangles on the 3D image, 3 corners each
  std::vector<std::vector<Eigen::Vector3d>> edges;  // the footprint's outline on the 3D image
  std::vector<std::vector<Eigen::Vector3d>> open;   // the image's border inside the footprint
  std::optional<Eigen::Vector3d> centre;            // on the surface: where its marker goes
  bool on_map() const { return !fill.empty() || !edges.empty(); }
};
BlockOnFace lay_block(const std::vector<Eigen::Vector3d>& footprint, const SurfaceDrape& drape);

// Laid blocks kept by their footprint (filling is a pass over the surface).
class BlockFaceCache {
 public:
  const BlockOnFace& get(const std::vector<Eigen::Vector3d>& footprint, const SurfaceDrape& drape);
  void clear() { cache_.clear(); }

 private:
  std::map<std::vector<double>, BlockOnFace> cache_;
};

// Adds a laid block to an overlay: tinted when finite, outlined in its
// colour, the open border dashed.
void add_block_to_overlay(OverlayScene& overlay, const std::string& label, const BlockOnFace& block,
                          ImU32 colour, bool finite, float width_px);

// The Blocks screen's stored blocks, and the footprint of one on the screen
// (the convex hull of its laid lines, projected; empty when not on the 3D
// image), for tapping and its marker.
void add_blocks_to_overlay(AppState& app);
std::vector<ImVec2> block_outline_on_screen(AppState& app, const BlockView& block);
// Where a block's marker goes on the screen: its centre on the surface.
std::optional<ImVec2> block_marker_on_screen(AppState& app, const BlockView& block);

}  // namespace rockface::ui
