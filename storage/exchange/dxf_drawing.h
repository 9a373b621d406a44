#pragma once
// A DXF drawing (AutoCAD 2000, what AutoCAD, Civil 3D, BricsCAD and ezdxf
// open) of 3D lines and closed meshes on named layers, written with dxflib.
//
// dxflib writes lines and polylines in 2D only (its polyline is an
// LWPOLYLINE), so 3D polylines and polyface meshes are written here with its
// writer's group codes: POLYLINE with flag 8 (3D) or 64 (polyface mesh),
// VERTEX records and SEQEND, as the DXF reference gives them.
//
// Coordinates are absolute (survey coordinates where the project has them):
// dxflib writes 16 decimals, so millimetres survive at 10^6 m; the header's
// $INSBASE holds nothing useful for that, so the offset is named in the
// file's comment instead.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace rockface::storage {

class DxfDrawing {
 public:
  // AutoCAD Color Index (1 red, 2 yellow, 3 green, 4 cyan, 5 blue, 6 magenta, 7 white/black).
  void add_layer(const std::string& name, int colour);

  // A 3D polyline on `layer` (added before); `closed` joins the last point to
  // the first. At least two points.
  void add_polyline(const std::string& layer, const std::vector<Eigen::Vector3d>& points,
                    bool closed);

  // A polyface mesh on `layer`: faces as triangles of indices into
  // `vertices` (a closed block: every edge shared by two triangles).
  void add_mesh(const std::string& layer, const std::vector<Eigen::Vector3d>& vertices,
                const std::vector<std::array<int, 3>>& triangles);

  void add_comment(const std::string& text) { comments_.push_back(text); }

  // Written under a temporary name and renamed (core/common/atomic_file's
  // rule): a failed export leaves no half file. Throws rockface::Error
  // naming the file when it cannot be written, InputError for a layer used
  // but not added, a non-finite coordinate or an index out of range.
  void write(const std::filesystem::path& file) const;

  std::size_t entity_count() const { return polylines_.size() + meshes_.size(); }

 private:
  struct Layer {
    std::string name;
    int colour = 7;
  };
  struct Polyline {
    std::string layer;
    std::vector<Eigen::Vector3d> points;
    bool closed = false;
  };
  struct MeshEntity {
    std::string layer;
    std::vector<Eigen::Vector3d> vertices;
    std::vector<std::array<int, 3>> triangles;
  };
  const Layer& layer_named(const std::string& name) const;

  std::vector<Layer> layers_;
  std::vector<Polyline> polylines_;
  std::vector<MeshEntity> meshes_;
  std::vector<std::string> comments_;
};

// A layer name AutoCAD accepts: letters, digits, '-' and '_' kept, anything
// else (spaces, '<', '/', ...) made '_'; upper case as AutoCAD shows them.
std::string dxf_layer_name(const std::string& text);

}  // namespace rockface::storage
