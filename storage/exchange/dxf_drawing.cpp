#include "storage/exchange/dxf_drawing.h"

#include <dxflib/dl_dxf.h>

#include <unistd.h>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>

#include "core/common/atomic_file.h"
#include "core/common/error.h"

namespace rockface::storage {

namespace {

// POLYLINE flags (DXF reference, group 70) and VERTEX flags.
constexpr int kPolyline3d = 8, kPolyfaceMesh = 64, kClosed = 1;
constexpr int kVertex3dPolyline = 32, kVertexPolyface = 128 | 64, kFaceRecord = 128;

bool finite_point(const Eigen::Vector3d& p) {
  return p.allFinite();
}

// The entity's common head: type, handle, subclass markers, layer.
void dxf_entity_head(DL_WriterA& dw, const char* type, const std::string& layer,
                     const char* subclass) {
  dw.entity(type);
  dw.subClass("AcDbEntity");
  dw.dxfString(8, layer);
  dw.subClass(subclass);
}

void dxf_vertex(DL_WriterA& dw, const std::string& layer, const char* subclass,
                const Eigen::Vector3d& p, int flags) {
  dxf_entity_head(dw, "VERTEX", layer, "AcDbVertex");
  dw.subClass(subclass);
  dw.coord(10, p.x(), p.y(), p.z());
  dw.dxfInt(70, flags);
}

void dxf_seqend(DL_WriterA& dw, const std::string& layer) {
  dw.entity("SEQEND");
  dw.subClass("AcDbEntity");
  dw.dxfString(8, layer);
}

}  // namespace

std::string dxf_layer_name(const std::string& text) {
  std::string name;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    name += (std::isalnum(u) || c == '-' || c == '_') ? static_cast<char>(std::toupper(u)) : '_';
  }
  return name.empty() ? std::string("UNNAMED") : name;
}

void DxfDrawing::add_layer(const std::string& name, int colour) {
  for (const auto& l : layers_)
    if (l.name == name) return;
  layers_.push_back({name, colour});
}

const DxfDrawing::Layer& DxfDrawing::layer_named(const std::string& name) const {
  for (const auto& l : layers_)
    if (l.name == name) return l;
  throw InputError("DXF drawing", "layer " + name + " is used but was not added");
}

void DxfDrawing::add_polyline(const std::string& layer, const std::vector<Eigen::Vector3d>& points,
                              bool closed) {
  layer_named(layer);
  if (points.size() < 2)
    throw InputError("DXF layer " + layer, "a polyline needs two points or more");
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!finite_point(points[i]))
      throw InputError("DXF layer " + layer,
                       "polyline point " + std::to_string(i) + " is not a finite number");
  polylines_.push_back({layer, points, closed});
}

void DxfDrawing::add_mesh(const std::string& layer, const std::vector<Eigen::Vector3d>& vertices,
                          const std::vector<std::array<int, 3>>& triangles) {
  layer_named(layer);
  for (std::size_t i = 0; i < vertices.size(); ++i)
    if (!finite_point(vertices[i]))
      throw InputError("DXF layer " + layer,
                       "mesh vertex " + std::to_string(i) + " is not a finite number");
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (const int i : triangles[t])
      if (i < 0 || i >= static_cast<int>(vertices.size()))
        throw InputError("DXF layer " + layer, "mesh triangle " + std::to_string(t) +
                                                   " names vertex " + std::to_string(i) + " of " +
                                                   std::to_string(vertices.size()));
  if (triangles.empty()) throw InputError("DXF layer " + layer, "a mesh without triangles");
  meshes_.push_back({layer, vertices, triangles});
}

void DxfDrawing::write(const std::filesystem::path& file) const {
  // dxflib writes to a file of its own opening: a temporary one beside the
  // target, then copied in through the atomic writer (synced, renamed).
  const std::filesystem::path partial =
      file.string() + ".dxflib-" + std::to_string(static_cast<long>(::getpid()));
  struct RemovePartial {
    std::filesystem::path path;
    ~RemovePartial() {
      std::error_code ec;
      std::filesystem::remove(path, ec);
    }
  } remove_partial{partial};
  {
    DL_Dxf dxf;
    std::unique_ptr<DL_WriterA> dw(dxf.out(partial.c_str(), DL_Codes::AC1015));
    if (!dw) throw Error(file.string() + ": cannot be written (dxflib could not open it)");
    for (const auto& c : comments_) dxf.writeComment(*dw, c);
    dxf.writeHeader(*dw);
    dw->sectionEnd();

    dw->sectionTables();
    dxf.writeVPort(*dw);
    dw->tableLinetypes(3);
    dxf.writeLinetype(*dw, DL_LinetypeData("BYBLOCK", "", 0, 0, 0.0));
    dxf.writeLinetype(*dw, DL_LinetypeData("BYLAYER", "", 0, 0, 0.0));
    dxf.writeLinetype(*dw, DL_LinetypeData("CONTINUOUS", "Solid line", 0, 0, 0.0));
    dw->tableEnd();
    dw->tableLayers(static_cast<int>(layers_.size()) + 1);
    dxf.writeLayer(*dw, DL_LayerData("0", 0),
                   DL_Attributes(std::string(), DL_Codes::black, 100, "CONTINUOUS", 1.0));
    for (const auto& l : layers_)
      dxf.writeLayer(*dw, DL_LayerData(l.name, 0),
                     DL_Attributes(std::string(), l.colour, 100, "CONTINUOUS", 1.0));
    dw->tableEnd();
    dw->tableStyle(1);
    dxf.writeStyle(*dw, DL_StyleData("standard", 0, 2.5, 1.0, 0.0, 0, 2.5, "txt", ""));
    dw->tableEnd();
    dxf.writeView(*dw);
    dxf.writeUcs(*dw);
    dw->tableAppid(1);
    dxf.writeAppid(*dw, "ACAD");
    dw->tableEnd();
    dxf.writeDimStyle(*dw, 1, 1, 1, 1, 1);
    dxf.writeBlockRecord(*dw);
    dw->tableEnd();
    dw->sectionEnd();

    dw->sectionBlocks();
    for (const char* space : {"*Model_Space", "*Paper_Space", "*Paper_Space0"}) {
      dxf.writeBlock(*dw, DL_BlockData(space, 0, 0.0, 0.0, 0.0));
      dxf.writeEndBlock(*dw, space);
    }
    dw->sectionEnd();

    dw->sectionEntities();
    for (const auto& p : polylines_) {
      dxf_entity_head(*dw, "POLYLINE", p.layer, "AcDb3dPolyline");
      dw->dxfInt(66, 1);
      dw->coord(10, 0.0, 0.0, 0.0);
      dw->dxfInt(70, kPolyline3d | (p.closed ? kClosed : 0));
      for (const auto& v : p.points)
        dxf_vertex(*dw, p.layer, "AcDb3dPolylineVertex", v, kVertex3dPolyline);
      dxf_seqend(*dw, p.layer);
    }
    for (const auto& m : meshes_) {
      dxf_entity_head(*dw, "POLYLINE", m.layer, "AcDbPolyFaceMesh");
      dw->dxfInt(66, 1);
      dw->coord(10, 0.0, 0.0, 0.0);
      dw->dxfInt(70, kPolyfaceMesh);
      dw->dxfInt(71, static_cast<int>(m.vertices.size()));
      dw->dxfInt(72, static_cast<int>(m.triangles.size()));
      for (const auto& v : m.vertices)
        dxf_vertex(*dw, m.layer, "AcDbPolyFaceMeshVertex", v, kVertexPolyface);
      for (const auto& t : m.triangles) {
        dxf_entity_head(*dw, "VERTEX", m.layer, "AcDbFaceRecord");
        dw->coord(10, 0.0, 0.0, 0.0);
        dw->dxfInt(70, kFaceRecord);
        // 1-based vertex numbers; every edge drawn (positive).
        dw->dxfInt(71, t[0] + 1);
        dw->dxfInt(72, t[1] + 1);
        dw->dxfInt(73, t[2] + 1);
      }
      dxf_seqend(*dw, m.layer);
    }
    dw->sectionEnd();

    dxf.writeObjects(*dw);
    dxf.writeObjectsEnd(*dw);
    dw->dxfEOF();
    dw->close();
  }
  std::ifstream in(partial, std::ios::binary);
  if (!in) throw Error(file.string() + ": cannot be written (its temporary file vanished)");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  write_text_atomically(file, bytes);
}

}  // namespace rockface::storage
