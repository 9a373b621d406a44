#include "storage/exchange/obj_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <unordered_map>

#include <tiny_obj_loader.h>

#include "core/common/error.h"

namespace rockface::storage {

namespace obj_detail {

// tinyobjloader reads "nan" and "inf" as 0: a vertex the file says is not a
// number would come back at the origin. Its lines are checked here first.
void refuse_non_numbers(std::string_view bytes, const std::string& source) {
  std::size_t pos = 0, line_no = 0;
  while (pos < bytes.size()) {
    std::size_t nl = bytes.find('\n', pos);
    if (nl == std::string_view::npos) nl = bytes.size();
    const std::string_view line = bytes.substr(pos, nl - pos);
    pos = nl + 1;
    ++line_no;
    if (line.size() < 2 || line[0] != 'v') continue;
    std::string lower(line);
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower.find("nan") != std::string::npos || lower.find("inf") != std::string::npos)
      throw InputError(source, "line " + std::to_string(line_no) + ": '" +
                                   std::string(line.substr(0, 60)) +
                                   "' holds a value that is not a finite number");
  }
}

}  // namespace obj_detail

ImportedSurface parse_obj(std::string_view bytes, const std::string& source,
                          const std::filesystem::path& material_dir) {
  obj_detail::refuse_non_numbers(bytes, source);
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  std::istringstream in{std::string(bytes)};
  const std::string dir = material_dir.empty() ? std::string() : material_dir.string() + "/";
  tinyobj::MaterialFileReader material_reader(dir);
  const bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &in,
                                   material_dir.empty() ? nullptr : &material_reader, true, false);
  if (!ok) {
    std::string why = err.empty() ? std::string("tinyobjloader cannot read it") : err;
    while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
    throw InputError(source, why);
  }
  const std::size_t nv = attrib.vertices.size() / 3;
  const std::size_t nt = attrib.texcoords.size() / 2;
  const bool colours = attrib.colors.size() == attrib.vertices.size() && nv > 0;

  ImportedSurface out;
  out.format = "OBJ";
  auto& mesh = out.mesh;
  for (std::size_t i = 0; i < nv; ++i) {
    const Eigen::Vector3d p(attrib.vertices[3 * i], attrib.vertices[3 * i + 1],
                            attrib.vertices[3 * i + 2]);
    require_finite_point(p, source, "vertex " + std::to_string(i + 1));
  }
  for (double t : attrib.texcoords)
    if (!std::isfinite(t)) throw InputError(source, "a texture coordinate is not finite");
  if (colours)
    for (double c : attrib.colors)
      if (!std::isfinite(c)) throw InputError(source, "a vertex colour is not finite");

  // Does any face use texture coordinates? Then each (vertex, texcoord) pair
  // is a vertex of its own; else the file's vertices are the mesh's.
  bool textured = false;
  for (const auto& s : shapes)
    for (const auto& idx : s.mesh.indices) textured = textured || idx.texcoord_index >= 0;
  auto add_vertex = [&](std::size_t v, int t) {
    mesh.vertices.emplace_back(attrib.vertices[3 * v], attrib.vertices[3 * v + 1],
                               attrib.vertices[3 * v + 2]);
    if (colours) {
      std::array<std::uint8_t, 3> c{};
      for (std::size_t k = 0; k < 3; ++k)
        c[k] = static_cast<std::uint8_t>(
            std::lround(std::clamp(static_cast<double>(attrib.colors[3 * v + k]), 0.0, 1.0) * 255));
      mesh.colours.push_back(c);
    }
    if (textured) {
      // OBJ's v points up; the project's texture coordinates point down.
      const std::array<float, 2> uv =
          t >= 0 ? std::array<float, 2>{static_cast<float>(attrib.texcoords[2 * t]),
                                        static_cast<float>(1 - attrib.texcoords[2 * t + 1])}
                 : std::array<float, 2>{0, 0};
      mesh.texcoords.push_back(uv);
    }
  };
  std::unordered_map<std::uint64_t, std::int32_t> split;
  if (!textured)
    for (std::size_t v = 0; v < nv; ++v) add_vertex(v, -1);
  int material = -1;
  for (const auto& s : shapes) {
    const auto& idx = s.mesh.indices;
    for (std::size_t f = 0; 3 * f + 2 < idx.size(); ++f) {
      std::array<std::int32_t, 3> tri{};
      for (std::size_t k = 0; k < 3; ++k) {
        const auto& i = idx[3 * f + k];
        const std::string where = "shape '" + s.name + "' face " + std::to_string(f + 1);
        if (i.vertex_index < 0 || static_cast<std::size_t>(i.vertex_index) >= nv)
          throw InputError(source, where + ": vertex " + std::to_string(i.vertex_index + 1) +
                                       " is not one of the " + std::to_string(nv) + " vertices");
        if (i.texcoord_index >= 0 && static_cast<std::size_t>(i.texcoord_index) >= nt)
          throw InputError(source, where + ": texture coordinate " +
                                       std::to_string(i.texcoord_index + 1) +
                                       " is not one of the " + std::to_string(nt));
        if (!textured) {
          tri[k] = i.vertex_index;
          continue;
        }
        const std::uint64_t key = static_cast<std::uint64_t>(i.vertex_index) * (nt + 1) +
                                  static_cast<std::uint64_t>(i.texcoord_index + 1);
        const auto [it, added] =
            split.emplace(key, static_cast<std::int32_t>(mesh.vertices.size()));
        if (added) add_vertex(static_cast<std::size_t>(i.vertex_index), i.texcoord_index);
        tri[k] = it->second;
      }
      if (material < 0 && f < s.mesh.material_ids.size()) material = s.mesh.material_ids[f];
      if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;  // no area
      mesh.faces.push_back(tri);
    }
  }
  if (mesh.vertices.empty()) throw InputError(source, "no vertices in the file");
  if (material >= 0 && static_cast<std::size_t>(material) < materials.size() &&
      !materials[static_cast<std::size_t>(material)].diffuse_texname.empty()) {
    const std::filesystem::path texture =
        material_dir / materials[static_cast<std::size_t>(material)].diffuse_texname;
    if (!std::filesystem::exists(texture))
      throw InputError(
          source, "its material names the texture " + texture.string() + ", which does not exist");
    out.texture_file = texture.string();
  }
  take_datum(out);
  return out;
}

ImportedSurface read_obj(const std::filesystem::path& file) {
  const std::string bytes = read_whole_file(file.string());
  return parse_obj(bytes, file.string(), file.parent_path().empty() ? "." : file.parent_path());
}

}  // namespace rockface::storage
