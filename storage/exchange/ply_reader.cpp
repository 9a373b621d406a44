#include "storage/exchange/ply_reader.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <optional>
#include <sstream>
#include <vector>

#include "core/common/error.h"
#include "core/common/number_format.h"

namespace rockface::storage {

namespace {

enum class Type { i8, u8, i16, u16, i32, u32, f32, f64 };
enum class Format { ascii, little, big };

std::optional<Type> type_named(std::string_view s) {
  if (s == "char" || s == "int8") return Type::i8;
  if (s == "uchar" || s == "uint8") return Type::u8;
  if (s == "short" || s == "int16") return Type::i16;
  if (s == "ushort" || s == "uint16") return Type::u16;
  if (s == "int" || s == "int32") return Type::i32;
  if (s == "uint" || s == "uint32") return Type::u32;
  if (s == "float" || s == "float32") return Type::f32;
  if (s == "double" || s == "float64") return Type::f64;
  return std::nullopt;
}

std::size_t size_of(Type t) {
  switch (t) {
    case Type::i8:
    case Type::u8:
      return 1;
    case Type::i16:
    case Type::u16:
      return 2;
    case Type::i32:
    case Type::u32:
    case Type::f32:
      return 4;
    case Type::f64:
      return 8;
  }
  return 1;
}

bool is_integer(Type t) {
  return t != Type::f32 && t != Type::f64;
}

struct Property {
  std::string name;
  Type type = Type::f32;  // the value's type (a list's items)
  bool list = false;
  Type count_type = Type::u8;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

// A whole word as a number (no trailing characters), or nothing.
template <typename T>
std::optional<T> number(std::string_view s) {
  T v{};
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

struct Header {
  Format format = Format::ascii;
  std::vector<Element> elements;
  std::optional<Eigen::Vector3d> datum;
  bool absolute = false;  // the datum was added to the coordinates
  std::string texture_file;
  std::size_t data_start = 0;
};

// The writer's frame comment: "... absolute (datum X Y Z added)" or
// "... relative to datum X Y Z".
void read_frame_comment(std::string_view comment, Header& h) {
  const auto at = comment.find("datum ");
  if (at == std::string_view::npos) return;
  const auto w = words(comment.substr(at + 6));
  if (w.size() < 3) return;
  Eigen::Vector3d d;
  for (int k = 0; k < 3; ++k) {
    const auto v = number<double>(w[static_cast<std::size_t>(k)]);
    if (!v || !std::isfinite(*v)) return;
    d[k] = *v;
  }
  h.datum = d;
  h.absolute = comment.find("absolute") != std::string_view::npos;
}

Header read_header(std::string_view bytes, const std::string& source) {
  Header h;
  std::size_t pos = 0;
  int line_no = 0;
  bool format_seen = false;
  auto fail = [&](const std::string& what) {
    throw InputError(source, "header line " + std::to_string(line_no) + ": " + what);
  };
  for (;;) {
    const auto nl = bytes.find('\n', pos);
    if (nl == std::string_view::npos) {
      ++line_no;
      fail(line_no == 1 ? "not a PLY file (no 'ply' line)" : "the header has no end_header line");
    }
    std::string_view line = bytes.substr(pos, nl - pos);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos = nl + 1;
    ++line_no;
    if (line_no == 1) {
      if (line != "ply") fail("not a PLY file (the first line is not 'ply')");
      continue;
    }
    const auto w = words(line);
    if (w.empty()) continue;
    if (w[0] == "end_header") break;
    if (w[0] == "comment" || w[0] == "obj_info") {
      const std::string_view text =
          line.substr(std::min(line.size(), line.find(w[0]) + w[0].size() + 1));
      if (w.size() >= 3 && w[1] == "TextureFile")
        h.texture_file = std::string(text.substr(text.find("TextureFile") + 12));
      else if (w.size() >= 2 && w[1] == "frame")
        read_frame_comment(text, h);
      continue;
    }
    if (w[0] == "format") {
      if (w.size() != 3) fail("format needs a kind and a version");
      if (w[1] == "ascii")
        h.format = Format::ascii;
      else if (w[1] == "binary_little_endian")
        h.format = Format::little;
      else if (w[1] == "binary_big_endian")
        h.format = Format::big;
      else
        fail("unknown format '" + std::string(w[1]) + "'");
      if (w[2] != "1.0") fail("version '" + std::string(w[2]) + "' (1.0 is known)");
      format_seen = true;
      continue;
    }
    if (w[0] == "element") {
      if (w.size() != 3) fail("element needs a name and a count");
      const auto count = number<std::uint64_t>(w[2]);
      if (!count) fail("element count '" + std::string(w[2]) + "' is not a whole number");
      h.elements.push_back({std::string(w[1]), *count, {}});
      continue;
    }
    if (w[0] == "property") {
      if (h.elements.empty()) fail("a property before any element");
      Property p;
      if (w.size() == 5 && w[1] == "list") {
        const auto c = type_named(w[2]), t = type_named(w[3]);
        if (!c || !t) fail("unknown list type '" + std::string(c ? w[3] : w[2]) + "'");
        if (!is_integer(*c)) fail("a list count must be of an integer type");
        p.list = true;
        p.count_type = *c;
        p.type = *t;
        p.name = std::string(w[4]);
      } else if (w.size() == 3 && w[1] != "list") {
        const auto t = type_named(w[1]);
        if (!t) fail("unknown property type '" + std::string(w[1]) + "'");
        p.type = *t;
        p.name = std::string(w[2]);
      } else {
        fail("property needs a type and a name (or list, two types and a name)");
      }
      h.elements.back().properties.push_back(p);
      continue;
    }
    fail("unknown keyword '" + std::string(w[0]) + "'");
  }
  if (!format_seen) throw InputError(source, "the header has no format line");
  h.data_start = pos;
  return h;
}

// The data after the header, read value by value.
class Body {
 public:
  Body(std::string_view bytes, std::size_t pos, Format format, const std::string& source)
      : bytes_(bytes), pos_(pos), format_(format), source_(source) {}

  std::size_t remaining() const { return bytes_.size() - pos_; }
  Format format() const { return format_; }

  // One value; `where` names it in errors.
  double read(Type t, const std::string& where) {
    return format_ == Format::ascii ? read_ascii(t, where) : read_binary(t, where);
  }

 private:
  double read_ascii(Type t, const std::string& where) {
    while (pos_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[pos_]))) ++pos_;
    const std::size_t start = pos_;
    while (pos_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[pos_]))) ++pos_;
    if (pos_ == start) throw InputError(source_, where + ": the file ends here");
    const std::string_view word = bytes_.substr(start, pos_ - start);
    if (is_integer(t)) {
      const auto v = number<std::int64_t>(word);
      if (!v)
        throw InputError(source_, where + ": '" + std::string(word) + "' is not a whole number");
      return static_cast<double>(in_range(*v, t, where));
    }
    const auto v = number<double>(word);
    if (!v) throw InputError(source_, where + ": '" + std::string(word) + "' is not a number");
    return t == Type::f32 ? static_cast<double>(static_cast<float>(*v)) : *v;
  }

  std::int64_t in_range(std::int64_t v, Type t, const std::string& where) const {
    std::int64_t lo = 0, hi = 0;
    switch (t) {
      case Type::i8:
        lo = -128, hi = 127;
        break;
      case Type::u8:
        lo = 0, hi = 255;
        break;
      case Type::i16:
        lo = -32768, hi = 32767;
        break;
      case Type::u16:
        lo = 0, hi = 65535;
        break;
      case Type::i32:
        lo = std::numeric_limits<std::int32_t>::min(),
        hi = std::numeric_limits<std::int32_t>::max();
        break;
      default:
        lo = 0, hi = std::numeric_limits<std::uint32_t>::max();
        break;
    }
    if (v < lo || v > hi)
      throw InputError(source_, where + ": " + std::to_string(v) + " is out of its type's range");
    return v;
  }

  template <typename T>
  T take() {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    const bool swap = (format_ == Format::big) != (std::endian::native == std::endian::big);
    if (swap) std::reverse(raw, raw + sizeof(T));
    T v;
    std::memcpy(&v, raw, sizeof(T));
    return v;
  }

  double read_binary(Type t, const std::string& where) {
    if (remaining() < size_of(t)) throw InputError(source_, where + ": the file ends here");
    switch (t) {
      case Type::i8:
        return take<std::int8_t>();
      case Type::u8:
        return take<std::uint8_t>();
      case Type::i16:
        return take<std::int16_t>();
      case Type::u16:
        return take<std::uint16_t>();
      case Type::i32:
        return take<std::int32_t>();
      case Type::u32:
        return take<std::uint32_t>();
      case Type::f32:
        return take<float>();
      case Type::f64:
        return take<double>();
    }
    return 0;
  }

  std::string_view bytes_;
  std::size_t pos_;
  Format format_;
  const std::string& source_;
};

// The fewest bytes one record of `e` takes, so a count the file cannot hold
// is refused before anything is allocated for it.
std::size_t min_record_bytes(const Element& e, Format f) {
  std::size_t n = 0;
  for (const Property& p : e.properties)
    n += f == Format::ascii ? 2 : size_of(p.list ? p.count_type : p.type);
  return n;
}

std::optional<std::size_t> find(const Element& e, std::initializer_list<std::string_view> names) {
  for (std::string_view name : names)
    for (std::size_t i = 0; i < e.properties.size(); ++i)
      if (!e.properties[i].list && e.properties[i].name == name) return i;
  return std::nullopt;
}

}  // namespace

PlyModel parse_ply(std::string_view bytes, const std::string& source) {
  const Header h = read_header(bytes, source);
  const Element* vertex = nullptr;
  for (const Element& e : h.elements)
    if (e.name == "vertex") vertex = &e;
  if (!vertex) throw InputError(source, "no vertex element in the header");
  const auto x = find(*vertex, {"x"}), y = find(*vertex, {"y"}), z = find(*vertex, {"z"});
  if (!x || !y || !z) throw InputError(source, "the vertex element has no x, y and z");
  const auto r = find(*vertex, {"red", "diffuse_red"}),
             g = find(*vertex, {"green", "diffuse_green"}),
             b = find(*vertex, {"blue", "diffuse_blue"});
  const bool colours = r && g && b;
  const auto u = find(*vertex, {"texture_u", "s", "u"}), v = find(*vertex, {"texture_v", "t", "v"});
  const bool texcoords = u && v;
  if (vertex->count > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
    throw InputError(source, "vertex count " + std::to_string(vertex->count) + " is too large");

  PlyModel out;
  out.texture_file = h.texture_file;
  auto& mesh = out.mesh;
  Body body(bytes, h.data_start, h.format, source);
  std::vector<double> values;
  for (const Element& e : h.elements) {
    if (e.properties.empty()) continue;  // takes no bytes, whatever its count
    const std::size_t min_bytes = min_record_bytes(e, h.format);
    if (min_bytes > 0 && e.count > body.remaining() / min_bytes + 1)
      throw InputError(source, "element " + e.name + ": " + std::to_string(e.count) +
                                   " records do not fit in the file's " +
                                   std::to_string(body.remaining()) + " bytes of data");
    const bool is_vertex = &e == vertex, is_face = e.name == "face";
    std::optional<std::size_t> indices;
    if (is_face) {
      for (std::size_t i = 0; i < e.properties.size(); ++i)
        if (e.properties[i].list &&
            (e.properties[i].name == "vertex_indices" || e.properties[i].name == "vertex_index"))
          indices = i;
      if (!indices && e.count > 0)
        throw InputError(source, "the face element has no vertex_indices list");
    }
    if (is_vertex) {
      mesh.vertices.reserve(e.count);
      if (colours) mesh.colours.reserve(e.count);
      if (texcoords) mesh.texcoords.reserve(e.count);
    }
    values.assign(e.properties.size(), 0.0);
    std::vector<int> polygon;
    for (std::uint64_t n = 0; n < e.count; ++n) {
      const std::string record = e.name + " " + std::to_string(n);
      for (std::size_t i = 0; i < e.properties.size(); ++i) {
        const Property& p = e.properties[i];
        const std::string where = record + ": " + p.name;
        if (!p.list) {
          values[i] = body.read(p.type, where);
          continue;
        }
        const double count = body.read(p.count_type, where + " count");
        if (count < 0) throw InputError(source, where + ": a negative count");
        if (count > static_cast<double>(body.remaining()))
          throw InputError(source, where + ": " + std::to_string(static_cast<long long>(count)) +
                                       " items do not fit in the rest of the file");
        const bool keep = indices && i == *indices;
        if (keep) polygon.clear();
        for (long long k = 0; k < static_cast<long long>(count); ++k) {
          const double item = body.read(p.type, where);
          if (!keep) continue;
          if (item != std::floor(item) || item < 0 || item >= static_cast<double>(vertex->count))
            throw InputError(source, where + ": vertex index " + format_significant(item, 6) +
                                         " is not one of the " + std::to_string(vertex->count) +
                                         " vertices");
          polygon.push_back(static_cast<int>(item));
        }
        if (keep && polygon.size() < 3)
          throw InputError(source, where + ": a face needs three vertices, this has " +
                                       std::to_string(polygon.size()));
      }
      if (is_vertex) {
        const Eigen::Vector3d p(values[*x], values[*y], values[*z]);
        for (int k = 0; k < 3; ++k)
          if (!std::isfinite(p[k]))
            throw InputError(source,
                             record + ": " + "xyz"[k] + std::string(" is not a finite number"));
        mesh.vertices.push_back(p);
        if (colours) {
          std::array<std::uint8_t, 3> c{};
          const std::size_t at[3] = {*r, *g, *b};
          for (int k = 0; k < 3; ++k) {
            const Property& cp = e.properties[at[k]];
            double value = values[at[k]];
            if (!is_integer(cp.type)) value *= 255.0;  // float colours are 0..1
            if (!std::isfinite(value)) value = 0;
            c[static_cast<std::size_t>(k)] =
                static_cast<std::uint8_t>(std::clamp(std::round(value), 0.0, 255.0));
          }
          mesh.colours.push_back(c);
        }
        if (texcoords) {
          const std::array<float, 2> t{static_cast<float>(values[*u]),
                                       static_cast<float>(values[*v])};
          if (!std::isfinite(t[0]) || !std::isfinite(t[1]))
            throw InputError(source, record + ": a texture coordinate is not finite");
          mesh.texcoords.push_back(t);
        }
      }
      if (is_face && indices)
        for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
          const std::array<int, 3> tri{polygon[0], polygon[k], polygon[k + 1]};
          if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;  // no area
          mesh.faces.push_back(tri);
        }
    }
  }

  // Datum-relative coordinates: the writer's datum, or for coordinates of
  // survey size (beyond 10 km) the first vertex rounded to metres.
  if (h.datum) {
    out.datum = *h.datum;
    if (h.absolute)
      for (auto& p : mesh.vertices) p -= out.datum;
  } else if (!mesh.vertices.empty()) {
    double largest = 0;
    for (const auto& p : mesh.vertices) largest = std::max(largest, p.cwiseAbs().maxCoeff());
    if (largest > 1e4) {
      out.datum = mesh.vertices.front().array().round().matrix();
      for (auto& p : mesh.vertices) p -= out.datum;
    }
  }
  return out;
}

PlyModel read_ply_mesh(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), "cannot open the file");
  std::ostringstream s;
  s << in.rdbuf();
  if (!in.good() && !in.eof()) throw InputError(file.string(), "cannot read the file");
  const std::string bytes = s.str();
  return parse_ply(bytes, file.string());
}

}  // namespace rockface::storage
