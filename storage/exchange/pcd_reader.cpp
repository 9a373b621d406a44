#include "storage/exchange/pcd_reader.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

#include "core/common/error.h"

namespace rockface::storage {

namespace pcd_detail {

struct PcdField {
  std::string name;
  std::size_t size = 4;
  char type = 'F';  // F float, I signed, U unsigned
  std::size_t count = 1;
  std::size_t offset = 0;  // in a binary record
};

std::vector<std::string_view> pcd_words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

template <typename T>
std::optional<T> pcd_number(std::string_view s) {
  T v{};
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

// One binary value as a double (little-endian, as PCL writes on x86).
double binary_value(const char* at, const PcdField& f) {
  auto load = [&](auto v) {
    std::memcpy(&v, at, sizeof(v));
    return static_cast<double>(v);
  };
  if (f.type == 'F') return f.size == 8 ? load(double{}) : load(float{});
  if (f.type == 'U') {
    if (f.size == 1) return load(std::uint8_t{});
    if (f.size == 2) return load(std::uint16_t{});
    if (f.size == 4) return load(std::uint32_t{});
    return load(std::uint64_t{});
  }
  if (f.size == 1) return load(std::int8_t{});
  if (f.size == 2) return load(std::int16_t{});
  if (f.size == 4) return load(std::int32_t{});
  return load(std::int64_t{});
}

// PCL packs a colour into the four bytes of a float (or a uint32):
// 0x00RRGGBB.
std::array<std::uint8_t, 3> unpack_rgb(const char* at) {
  std::uint32_t v = 0;
  std::memcpy(&v, at, 4);
  return {static_cast<std::uint8_t>(v >> 16), static_cast<std::uint8_t>(v >> 8),
          static_cast<std::uint8_t>(v)};
}

std::array<std::uint8_t, 3> unpack_rgb_ascii(std::string_view word, const PcdField& f,
                                             const std::string& source, const std::string& where) {
  std::uint32_t v = 0;
  if (f.type == 'F') {
    const auto d = pcd_number<float>(word);
    if (!d) throw InputError(source, where + ": rgb '" + std::string(word) + "' is not a number");
    std::memcpy(&v, &*d, 4);
  } else {
    const auto u = pcd_number<std::uint64_t>(word);
    if (!u || *u > 0xFFFFFFFFull)
      throw InputError(source, where + ": rgb '" + std::string(word) + "' is not a packed colour");
    v = static_cast<std::uint32_t>(*u);
  }
  char raw[4];
  std::memcpy(raw, &v, 4);
  return unpack_rgb(raw);
}

// What the header says: the fields, the cloud's shape, the data's kind and
// where the data begin.
struct PcdHeader {
  std::vector<PcdField> fields;
  std::uint64_t width = 0, height = 1, points = 0;
  bool points_seen = false;
  std::string data;     // "ascii" | "binary" | ... (empty until the DATA line)
  std::size_t pos = 0;  // the first byte after the header
};

// One header line's values for the fields named so far (SIZE, TYPE, COUNT).
void read_pcd_field_line(const std::vector<std::string_view>& w, const std::string& where,
                         const std::string& source, std::vector<PcdField>& fields) {
  if (w.size() - 1 != fields.size())
    throw InputError(source, where + ": " + std::string(w[0]) + " gives " +
                                 std::to_string(w.size() - 1) + " values for " +
                                 std::to_string(fields.size()) + " fields");
  auto whole = [&](std::string_view s) {
    const auto v = pcd_number<std::uint64_t>(s);
    if (!v) throw InputError(source, where + ": '" + std::string(s) + "' is not a whole number");
    return *v;
  };
  for (std::size_t i = 0; i < fields.size(); ++i) {
    PcdField& f = fields[i];
    const std::string_view word = w[i + 1];
    if (w[0] == "SIZE") {
      f.size = whole(word);
      if (f.size != 1 && f.size != 2 && f.size != 4 && f.size != 8)
        throw InputError(source, where + ": field " + f.name + " has size " +
                                     std::to_string(f.size) + " (1, 2, 4 or 8)");
    } else if (w[0] == "TYPE") {
      if (word.size() != 1 || std::string_view("FIU").find(word[0]) == std::string::npos)
        throw InputError(source, where + ": type '" + std::string(word) + "' (F, I or U)");
      f.type = word[0];
    } else {  // COUNT
      f.count = whole(word);
      if (f.count < 1 || f.count > 4096)
        throw InputError(source, where + ": field " + f.name + " count " + std::to_string(f.count) +
                                     " (1 to 4096)");
    }
  }
}

// The header's lines up to DATA, each checked as it is read.
PcdHeader read_pcd_header(std::string_view bytes, const std::string& source) {
  PcdHeader h;
  std::size_t line_no = 0;
  while (h.data.empty()) {
    if (h.pos >= bytes.size()) throw InputError(source, "the header has no DATA line");
    std::size_t nl = bytes.find('\n', h.pos);
    if (nl == std::string_view::npos) nl = bytes.size();
    const std::string_view line = bytes.substr(h.pos, nl - h.pos);
    h.pos = nl + 1;
    ++line_no;
    const auto w = pcd_words(line);
    const std::string where = "header line " + std::to_string(line_no);
    if (w.empty() || w[0].front() == '#') continue;
    auto whole = [&](std::string_view s) {
      const auto v = pcd_number<std::uint64_t>(s);
      if (!v) throw InputError(source, where + ": '" + std::string(s) + "' is not a whole number");
      return *v;
    };
    if (w[0] == "VERSION" || w[0] == "VIEWPOINT") continue;
    if (w[0] == "FIELDS") {
      for (std::size_t i = 1; i < w.size(); ++i) h.fields.push_back({std::string(w[i])});
      if (h.fields.empty()) throw InputError(source, where + ": no fields");
    } else if (w[0] == "SIZE" || w[0] == "TYPE" || w[0] == "COUNT") {
      read_pcd_field_line(w, where, source, h.fields);
    } else if (w[0] == "WIDTH" && w.size() == 2) {
      h.width = whole(w[1]);
    } else if (w[0] == "HEIGHT" && w.size() == 2) {
      h.height = whole(w[1]);
    } else if (w[0] == "POINTS" && w.size() == 2) {
      h.points = whole(w[1]);
      h.points_seen = true;
    } else if (w[0] == "DATA" && w.size() == 2) {
      h.data = std::string(w[1]);
    } else {
      throw InputError(source,
                       where + ": unknown header line '" + std::string(line.substr(0, 40)) + "'");
    }
  }
  return h;
}

// The data's kind read here, and the cloud's shape agreeing with its count
// (POINTS, else WIDTH x HEIGHT).
void check_pcd_shape(PcdHeader& h, const std::string& source) {
  if (h.data == "binary_compressed")
    throw InputError(
        source, "DATA binary_compressed: convert it first, e.g. `pcl_convert_pcd_ascii_binary " +
                    source + " cloud.pcd 1` (pcl-tools) or CloudCompare's Save as PCD");
  if (h.data != "ascii" && h.data != "binary")
    throw InputError(source, "DATA '" + h.data + "' (ascii or binary are read)");
  if (!h.points_seen) h.points = h.width * h.height;
  if (h.width == 0 || h.height == 0 || h.width > h.points || h.points / h.width != h.height ||
      h.points % h.width != 0)
    throw InputError(source, "the header's WIDTH " + std::to_string(h.width) + " x HEIGHT " +
                                 std::to_string(h.height) + " is not its POINTS " +
                                 std::to_string(h.points));
}

// Which fields hold the coordinates, the colour and the normals, and a
// binary record's length (each field's offset set in it).
struct PcdColumns {
  std::size_t record = 0;
  std::optional<std::size_t> x, y, z, rgb, nx, ny, nz;
  bool normals() const { return nx && ny && nz; }
};

PcdColumns place_pcd_fields(std::vector<PcdField>& fields, const std::string& source) {
  PcdColumns c;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    PcdField& f = fields[i];
    f.offset = c.record;
    c.record += f.size * f.count;
    const bool single = f.count == 1;
    if (f.name == "x" && single) c.x = i;
    if (f.name == "y" && single) c.y = i;
    if (f.name == "z" && single) c.z = i;
    if ((f.name == "rgb" || f.name == "rgba") && single && f.size == 4) c.rgb = i;
    if (f.name == "normal_x" && single) c.nx = i;
    if (f.name == "normal_y" && single) c.ny = i;
    if (f.name == "normal_z" && single) c.nz = i;
  }
  if (!c.x || !c.y || !c.z) throw InputError(source, "the header has no x, y and z fields");
  return c;
}

// Point n of binary data: the coordinates and normals into values, the
// colour into colour.
void read_binary_pcd_point(std::string_view bytes, const PcdHeader& h, const PcdColumns& c,
                           std::uint64_t n, std::vector<double>& values,
                           std::array<std::uint8_t, 3>& colour) {
  const char* at = bytes.data() + h.pos + n * c.record;
  const bool normals = c.normals();
  for (std::size_t i = 0; i < h.fields.size(); ++i)
    if (i == *c.x || i == *c.y || i == *c.z ||
        (normals && (i == *c.nx || i == *c.ny || i == *c.nz)))
      values[i] = binary_value(at + h.fields[i].offset, h.fields[i]);
  if (c.rgb) colour = unpack_rgb(at + h.fields[*c.rgb].offset);
}

// The next line of ASCII data (from pos, moved past it): every single
// field's number into values ("nan" a NaN), the colour into colour.
void read_ascii_pcd_point(std::string_view bytes, const PcdHeader& h, const PcdColumns& c,
                          const std::string& source, const std::string& where, std::size_t& pos,
                          std::vector<double>& values, std::array<std::uint8_t, 3>& colour) {
  if (pos >= bytes.size()) throw InputError(source, where + ": the file ends here");
  std::size_t nl = bytes.find('\n', pos);
  if (nl == std::string_view::npos) nl = bytes.size();
  const std::vector<std::string_view> words = pcd_words(bytes.substr(pos, nl - pos));
  pos = nl + 1;
  std::size_t expected = 0;
  for (const auto& f : h.fields) expected += f.count;
  if (words.size() != expected)
    throw InputError(source, where + ": " + std::to_string(words.size()) + " values, " +
                                 std::to_string(expected) + " expected");
  std::size_t k = 0;
  for (std::size_t i = 0; i < h.fields.size(); ++i) {
    if (c.rgb && i == *c.rgb) {
      colour = unpack_rgb_ascii(words[k], h.fields[i], source, where);
    } else if (h.fields[i].count == 1) {
      const std::string_view word = words[k];
      const bool nan_word = word == "nan" || word == "NaN" || word == "-nan";
      const auto v = pcd_number<double>(word);
      if (!v && !nan_word)
        throw InputError(source, where + ": " + h.fields[i].name + " '" +
                                     std::string(word.substr(0, 40)) + "' is not a number");
      values[i] = v ? *v : std::nan("");
    }
    k += h.fields[i].count;
  }
}

}  // namespace pcd_detail

ImportedSurface parse_pcd(std::string_view bytes, const std::string& source) {
  using namespace pcd_detail;
  if (std::endian::native != std::endian::little)
    throw Error("the PCD reader expects a little-endian machine");
  PcdHeader h = read_pcd_header(bytes, source);
  check_pcd_shape(h, source);
  const PcdColumns c = place_pcd_fields(h.fields, source);
  const bool normals = c.normals();
  const std::size_t remaining = bytes.size() - std::min(h.pos, bytes.size());
  const std::size_t least = h.data == "binary" ? c.record : 2 * h.fields.size();
  if (h.points > remaining / least)
    throw InputError(source, std::to_string(h.points) + " points do not fit in the file's " +
                                 std::to_string(remaining) + " bytes of data");

  ImportedSurface out;
  out.format = "PCD " + h.data;
  auto& mesh = out.mesh;
  mesh.vertices.reserve(h.points);
  if (c.rgb) mesh.colours.reserve(h.points);
  std::vector<double> values(h.fields.size());
  std::size_t pos = h.pos;
  for (std::uint64_t n = 0; n < h.points; ++n) {
    const std::string where = "point " + std::to_string(n);
    std::array<std::uint8_t, 3> colour{};
    if (h.data == "binary")
      read_binary_pcd_point(bytes, h, c, n, values, colour);
    else
      read_ascii_pcd_point(bytes, h, c, source, where, pos, values, colour);
    const Eigen::Vector3d p(values[*c.x], values[*c.y], values[*c.z]);
    if (h.height > 1 && p.array().isNaN().all()) {  // an organised cloud's pixel with no return
      ++out.skipped_points;
      continue;
    }
    require_finite_point(p, source, where);
    mesh.vertices.push_back(p);
    if (c.rgb) mesh.colours.push_back(colour);
    if (normals) {
      const Eigen::Vector3f nrm(static_cast<float>(values[*c.nx]),
                                static_cast<float>(values[*c.ny]),
                                static_cast<float>(values[*c.nz]));
      out.normals.push_back(nrm.allFinite() ? nrm : Eigen::Vector3f::Zero());
    }
  }
  if (mesh.vertices.empty()) throw InputError(source, "no points in the file");
  take_datum(out);
  return out;
}

}  // namespace rockface::storage
