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

}  // namespace pcd_detail

ImportedSurface parse_pcd(std::string_view bytes, const std::string& source) {
  using namespace pcd_detail;
  if (std::endian::native != std::endian::little)
    throw Error("the PCD reader expects a little-endian machine");
  std::vector<PcdField> fields;
  std::uint64_t width = 0, height = 1, points = 0;
  bool points_seen = false;
  std::string data;
  std::size_t pos = 0, line_no = 0;
  while (data.empty()) {
    if (pos >= bytes.size()) throw InputError(source, "the header has no DATA line");
    std::size_t nl = bytes.find('\n', pos);
    if (nl == std::string_view::npos) nl = bytes.size();
    const std::string_view line = bytes.substr(pos, nl - pos);
    pos = nl + 1;
    ++line_no;
    const auto w = pcd_words(line);
    const std::string where = "header line " + std::to_string(line_no);
    if (w.empty() || w[0].front() == '#') continue;
    auto need_fields = [&](std::size_t n) {
      if (w.size() - 1 != n)
        throw InputError(source, where + ": " + std::string(w[0]) + " gives " +
                                     std::to_string(w.size() - 1) + " values for " +
                                     std::to_string(n) + " fields");
    };
    auto whole = [&](std::string_view s) {
      const auto v = pcd_number<std::uint64_t>(s);
      if (!v) throw InputError(source, where + ": '" + std::string(s) + "' is not a whole number");
      return *v;
    };
    if (w[0] == "VERSION" || w[0] == "VIEWPOINT") continue;
    if (w[0] == "FIELDS") {
      for (std::size_t i = 1; i < w.size(); ++i) fields.push_back({std::string(w[i])});
      if (fields.empty()) throw InputError(source, where + ": no fields");
    } else if (w[0] == "SIZE") {
      need_fields(fields.size());
      for (std::size_t i = 0; i < fields.size(); ++i) {
        fields[i].size = whole(w[i + 1]);
        if (fields[i].size != 1 && fields[i].size != 2 && fields[i].size != 4 &&
            fields[i].size != 8)
          throw InputError(source, where + ": field " + fields[i].name + " has size " +
                                       std::to_string(fields[i].size) + " (1, 2, 4 or 8)");
      }
    } else if (w[0] == "TYPE") {
      need_fields(fields.size());
      for (std::size_t i = 0; i < fields.size(); ++i) {
        if (w[i + 1].size() != 1 || std::string_view("FIU").find(w[i + 1][0]) == std::string::npos)
          throw InputError(source, where + ": type '" + std::string(w[i + 1]) + "' (F, I or U)");
        fields[i].type = w[i + 1][0];
      }
    } else if (w[0] == "COUNT") {
      need_fields(fields.size());
      for (std::size_t i = 0; i < fields.size(); ++i) {
        fields[i].count = whole(w[i + 1]);
        if (fields[i].count < 1 || fields[i].count > 4096)
          throw InputError(source, where + ": field " + fields[i].name + " count " +
                                       std::to_string(fields[i].count) + " (1 to 4096)");
      }
    } else if (w[0] == "WIDTH" && w.size() == 2) {
      width = whole(w[1]);
    } else if (w[0] == "HEIGHT" && w.size() == 2) {
      height = whole(w[1]);
    } else if (w[0] == "POINTS" && w.size() == 2) {
      points = whole(w[1]);
      points_seen = true;
    } else if (w[0] == "DATA" && w.size() == 2) {
      data = std::string(w[1]);
    } else {
      throw InputError(source,
                       where + ": unknown header line '" + std::string(line.substr(0, 40)) + "'");
    }
  }
  if (data == "binary_compressed")
    throw InputError(
        source, "DATA binary_compressed: convert it first, e.g. `pcl_convert_pcd_ascii_binary " +
                    source + " cloud.pcd 1` (pcl-tools) or CloudCompare's Save as PCD");
  if (data != "ascii" && data != "binary")
    throw InputError(source, "DATA '" + data + "' (ascii or binary are read)");
  if (!points_seen) points = width * height;
  if (width == 0 || height == 0 || width > points || points / width != height ||
      points % width != 0)
    throw InputError(source, "the header's WIDTH " + std::to_string(width) + " x HEIGHT " +
                                 std::to_string(height) + " is not its POINTS " +
                                 std::to_string(points));
  std::size_t record = 0;
  std::optional<std::size_t> x, y, z, rgb, nx, ny, nz;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    PcdField& f = fields[i];
    f.offset = record;
    record += f.size * f.count;
    const bool single = f.count == 1;
    if (f.name == "x" && single) x = i;
    if (f.name == "y" && single) y = i;
    if (f.name == "z" && single) z = i;
    if ((f.name == "rgb" || f.name == "rgba") && single && f.size == 4) rgb = i;
    if (f.name == "normal_x" && single) nx = i;
    if (f.name == "normal_y" && single) ny = i;
    if (f.name == "normal_z" && single) nz = i;
  }
  if (!x || !y || !z) throw InputError(source, "the header has no x, y and z fields");
  const bool normals = nx && ny && nz;
  const std::size_t remaining = bytes.size() - std::min(pos, bytes.size());
  const std::size_t least = data == "binary" ? record : 2 * fields.size();
  if (points > remaining / least)
    throw InputError(source, std::to_string(points) + " points do not fit in the file's " +
                                 std::to_string(remaining) + " bytes of data");

  ImportedSurface out;
  out.format = "PCD " + data;
  auto& mesh = out.mesh;
  mesh.vertices.reserve(points);
  if (rgb) mesh.colours.reserve(points);
  std::vector<double> values(fields.size());
  std::vector<std::string_view> words;
  for (std::uint64_t n = 0; n < points; ++n) {
    const std::string where = "point " + std::to_string(n);
    std::array<std::uint8_t, 3> c{};
    if (data == "binary") {
      const char* at = bytes.data() + pos + n * record;
      for (std::size_t i = 0; i < fields.size(); ++i)
        if (i == *x || i == *y || i == *z || (normals && (i == *nx || i == *ny || i == *nz)))
          values[i] = binary_value(at + fields[i].offset, fields[i]);
      if (rgb) c = unpack_rgb(at + fields[*rgb].offset);
    } else {
      if (pos >= bytes.size()) throw InputError(source, where + ": the file ends here");
      std::size_t nl = bytes.find('\n', pos);
      if (nl == std::string_view::npos) nl = bytes.size();
      words = pcd_words(bytes.substr(pos, nl - pos));
      pos = nl + 1;
      std::size_t expected = 0;
      for (const auto& f : fields) expected += f.count;
      if (words.size() != expected)
        throw InputError(source, where + ": " + std::to_string(words.size()) + " values, " +
                                     std::to_string(expected) + " expected");
      std::size_t k = 0;
      for (std::size_t i = 0; i < fields.size(); ++i) {
        if (rgb && i == *rgb) {
          c = unpack_rgb_ascii(words[k], fields[i], source, where);
        } else if (fields[i].count == 1) {
          const std::string_view word = words[k];
          const bool nan_word = word == "nan" || word == "NaN" || word == "-nan";
          const auto v = pcd_number<double>(word);
          if (!v && !nan_word)
            throw InputError(source, where + ": " + fields[i].name + " '" +
                                         std::string(word.substr(0, 40)) + "' is not a number");
          values[i] = v ? *v : std::nan("");
        }
        k += fields[i].count;
      }
    }
    const Eigen::Vector3d p(values[*x], values[*y], values[*z]);
    if (height > 1 && p.array().isNaN().all()) {  // an organised cloud's pixel with no return
      ++out.skipped_points;
      continue;
    }
    require_finite_point(p, source, where);
    mesh.vertices.push_back(p);
    if (rgb) mesh.colours.push_back(c);
    if (normals) {
      const Eigen::Vector3f nrm(static_cast<float>(values[*nx]), static_cast<float>(values[*ny]),
                                static_cast<float>(values[*nz]));
      out.normals.push_back(nrm.allFinite() ? nrm : Eigen::Vector3f::Zero());
    }
  }
  if (mesh.vertices.empty()) throw InputError(source, "no points in the file");
  take_datum(out);
  return out;
}

}  // namespace rockface::storage
