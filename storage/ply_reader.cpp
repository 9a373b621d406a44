#include "storage/ply_reader.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/common/error.h"

namespace rockface::storage {

namespace {

struct Property {
  std::string name, type;
  bool list = false;
  std::string count_type;
};

int type_size(const std::string& t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32")
    return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

template <typename T>
double load(const char* p) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  return static_cast<double>(v);
}

double binary_value(const std::string& t, const char* p) {
  if (t == "char" || t == "int8") return load<std::int8_t>(p);
  if (t == "uchar" || t == "uint8") return load<std::uint8_t>(p);
  if (t == "short" || t == "int16") return load<std::int16_t>(p);
  if (t == "ushort" || t == "uint16") return load<std::uint16_t>(p);
  if (t == "int" || t == "int32") return load<std::int32_t>(p);
  if (t == "uint" || t == "uint32") return load<std::uint32_t>(p);
  if (t == "float" || t == "float32") return load<float>(p);
  return load<double>(p);
}

// Reads one value of `type` from the body (binary or ascii).
class Body {
 public:
  Body(std::istream& in, bool binary, std::string where)
      : in_(in), binary_(binary), where_(std::move(where)) {}
  double next(const std::string& type, const char* what) {
    if (binary_) {
      char buf[8];
      const int n = type_size(type);
      if (!in_.read(buf, n)) throw InputError(where_, std::string("cut short in ") + what);
      return binary_value(type, buf);
    }
    double v;
    if (!(in_ >> v)) throw InputError(where_, std::string("cut short or not a number in ") + what);
    return v;
  }

 private:
  std::istream& in_;
  bool binary_;
  std::string where_;
};

}  // namespace

PlyModel read_ply_mesh(const std::filesystem::path& file) {
  const std::string where = file.string();
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(where, "cannot open the model file");
  std::string line;
  if (!std::getline(in, line) || line.substr(0, 3) != "ply")
    throw InputError(where, "not a PLY file (no \"ply\" on the first line)");
  PlyModel out;
  bool binary = false;
  bool absolute = false;  // the vertices have the datum added
  std::size_t vertices = 0, faces = 0;
  std::vector<Property> vertex_props, face_props;
  std::vector<Property>* current = nullptr;
  int line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream s(line);
    std::string word;
    s >> word;
    const std::string at = where + ": header line " + std::to_string(line_no);
    if (word == "end_header") break;
    if (word == "format") {
      std::string f;
      s >> f;
      if (f == "binary_little_endian")
        binary = true;
      else if (f != "ascii")
        throw InputError(at, "format \"" + f + "\" is not read (ascii or binary_little_endian)");
    } else if (word == "comment") {
      std::string rest;
      std::getline(s, rest);
      if (rest.size() > 1) rest.erase(0, 1);
      if (rest.rfind("TextureFile ", 0) == 0) out.texture_file = rest.substr(12);
      // "absolute (datum X Y Z added)" or "relative to datum X Y Z".
      for (const char* key : {"(datum ", "relative to datum "}) {
        const auto d = rest.find(key);
        if (d == std::string::npos) continue;
        std::istringstream ds(rest.substr(d + std::strlen(key)));
        ds >> out.datum.x() >> out.datum.y() >> out.datum.z();
        if (!ds) out.datum.setZero();
        absolute = key[0] == '(' && ds;
      }
    } else if (word == "element") {
      std::string name;
      std::size_t count = 0;
      s >> name >> count;
      if (name == "vertex") {
        vertices = count;
        current = &vertex_props;
      } else if (name == "face") {
        faces = count;
        current = &face_props;
      } else {
        throw InputError(at, "element \"" + name + "\" is not read (vertex and face only)");
      }
    } else if (word == "property") {
      if (!current) throw InputError(at, "property before any element");
      Property p;
      s >> p.type;
      if (p.type == "list") {
        p.list = true;
        s >> p.count_type >> p.type;
        if (type_size(p.count_type) == 0) throw InputError(at, "unknown type " + p.count_type);
      }
      s >> p.name;
      if (type_size(p.type) == 0) throw InputError(at, "unknown type " + p.type);
      current->push_back(p);
    } else if (!word.empty() && word != "obj_info") {
      throw InputError(at, "unknown header keyword \"" + word + "\"");
    }
  }
  if (!in) throw InputError(where, "the header has no end_header");
  bool has_xyz[3] = {false, false, false}, has_rgb = false, has_uv = false;
  for (const auto& p : vertex_props) {
    if (p.list) throw InputError(where, "a list property of vertices is not read");
    if (p.name == "x") has_xyz[0] = true;
    if (p.name == "y") has_xyz[1] = true;
    if (p.name == "z") has_xyz[2] = true;
    if (p.name == "red") has_rgb = true;
    if (p.name == "texture_u") has_uv = true;
  }
  if (!has_xyz[0] || !has_xyz[1] || !has_xyz[2])
    throw InputError(where, "the vertices have no x, y, z");
  if (face_props.size() != 1 || !face_props[0].list)
    throw InputError(where, "faces must have one list property (vertex_indices)");

  Body body(in, binary, where);
  Mesh& m = out.mesh;
  m.vertices.resize(vertices);
  if (has_rgb) m.colours.resize(vertices);
  if (has_uv) m.texcoords.resize(vertices);
  for (std::size_t i = 0; i < vertices; ++i) {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (const auto& prop : vertex_props) {
      const double v = body.next(prop.type, "the vertices");
      if (prop.name == "x")
        p.x() = v;
      else if (prop.name == "y")
        p.y() = v;
      else if (prop.name == "z")
        p.z() = v;
      else if (prop.name == "red")
        m.colours[i][0] = static_cast<std::uint8_t>(v);
      else if (prop.name == "green")
        m.colours[i][1] = static_cast<std::uint8_t>(v);
      else if (prop.name == "blue")
        m.colours[i][2] = static_cast<std::uint8_t>(v);
      else if (prop.name == "texture_u")
        m.texcoords[i][0] = static_cast<float>(v);
      else if (prop.name == "texture_v")
        m.texcoords[i][1] = static_cast<float>(v);
    }
    if (!p.allFinite()) throw InputError(where, "vertex " + std::to_string(i) + " is not finite");
    m.vertices[i] = absolute ? Eigen::Vector3d(p - out.datum) : p;
  }
  m.faces.resize(faces);
  const Property& list = face_props[0];
  for (std::size_t f = 0; f < faces; ++f) {
    const double n = body.next(list.count_type, "the faces");
    if (n != 3)
      throw InputError(where, "face " + std::to_string(f) + " has " + std::to_string(int(n)) +
                                  " vertices, not 3");
    for (int k = 0; k < 3; ++k) {
      const double v = body.next(list.type, "the faces");
      if (!(v >= 0 && v < static_cast<double>(vertices)))
        throw InputError(where, "face " + std::to_string(f) + " names vertex " +
                                    std::to_string(static_cast<long long>(v)) + " of " +
                                    std::to_string(vertices));
      m.faces[f][k] = static_cast<std::int32_t>(v);
    }
  }
  return out;
}

}  // namespace rockface::storage
