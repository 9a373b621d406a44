#include "storage/exchange/xyz_reader.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>

#include "core/common/error.h"

namespace rockface::storage {

namespace xyz_detail {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// A header's or a user's column name as the reader's own: "" when skipped,
// nothing when it is no name at all (a number: the line is data).
std::string canonical(std::string_view raw) {
  const std::string s = lower(raw);
  if (s == "x" || s == "e" || s == "east" || s == "easting" || s == "//x") return "x";
  if (s == "y" || s == "n" || s == "north" || s == "northing") return "y";
  if (s == "z" || s == "h" || s == "elevation" || s == "height" || s == "alt") return "z";
  if (s == "r" || s == "red") return "r";
  if (s == "g" || s == "green") return "g";
  if (s == "b" || s == "blue") return "b";
  if (s == "nx" || s == "normal_x") return "nx";
  if (s == "ny" || s == "normal_y") return "ny";
  if (s == "nz" || s == "normal_z") return "nz";
  if (s == "i" || s == "intensity" || s == "scalar_intensity") return "i";
  return "";
}

bool is_separator(char c) {
  return c == ',' || c == ';' || c == ' ' || c == '\t';
}

// The fields of one line; empty fields between separators are not fields
// ("1, 2, 3" has three).
void split(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_separator(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_separator(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
}

std::optional<double> number(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

// The columns a count says without doubt.
PointColumns columns_of_count(std::size_t count, bool pts) {
  if (count == 3) return {"x", "y", "z"};
  if (count == 4) return {"x", "y", "z", "i"};
  if (count == 6 && !pts) return {"x", "y", "z", "r", "g", "b"};
  if (count == 7 && pts) return {"x", "y", "z", "i", "r", "g", "b"};
  return {};
}

void check_columns(const PointColumns& c, const std::string& where) {
  for (const char* name : {"x", "y", "z"})
    if (std::count(c.begin(), c.end(), name) != 1)
      throw InputError(where, std::string("the columns must name ") + name + " once");
  for (const char* name : {"r", "g", "b", "nx", "ny", "nz", "i"})
    if (std::count(c.begin(), c.end(), name) > 1)
      throw InputError(where, std::string("the columns name ") + name + " more than once");
  const auto has = [&](const char* n) { return std::count(c.begin(), c.end(), n) == 1; };
  if ((has("r") || has("g") || has("b")) && !(has("r") && has("g") && has("b")))
    throw InputError(where, "colours need r, g and b");
  if ((has("nx") || has("ny") || has("nz")) && !(has("nx") && has("ny") && has("nz")))
    throw InputError(where, "normals need nx, ny and nz");
}

}  // namespace xyz_detail

PointColumns parse_point_columns(const std::string& text, const std::string& where) {
  PointColumns out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    const std::string name =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::string c = xyz_detail::canonical(name);
    if (c.empty() && name != "-" && xyz_detail::lower(name) != "skip")
      throw InputError(where, "'" + name +
                                  "' is no column name (x, y, z, r, g, b, nx, ny, nz, "
                                  "intensity, or - to skip)");
    out.push_back(c);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  xyz_detail::check_columns(out, where);
  return out;
}

ImportedSurface parse_xyz(std::string_view bytes, const std::string& source,
                          const PointColumns& given, bool pts) {
  using namespace xyz_detail;
  ImportedSurface out;
  out.format = pts ? "PTS text" : "text, one point a line";
  PointColumns columns = given;
  if (!columns.empty()) check_columns(columns, "--columns");
  std::optional<std::uint64_t> declared;  // PTS: the count on its first line
  std::size_t pos = 0, line_no = 0;
  std::vector<std::string_view> fields;
  std::vector<double> values;
  std::vector<std::array<double, 3>> colours;
  bool header_read = false;
  double largest_colour = 0;
  bool fractional_colour = false;
  const auto at = [&](const char* name) -> std::optional<std::size_t> {
    const auto it = std::find(columns.begin(), columns.end(), name);
    if (it == columns.end()) return std::nullopt;
    return static_cast<std::size_t>(it - columns.begin());
  };
  std::optional<std::size_t> x, y, z, r, g, b, nx, ny, nz, i;
  auto locate = [&] {
    x = at("x"), y = at("y"), z = at("z"), r = at("r"), g = at("g"), b = at("b");
    nx = at("nx"), ny = at("ny"), nz = at("nz");
    // The intensity is kept only where it is the colours to be
    // (intensity_grey.h).
    i = r ? std::nullopt : at("i");
  };
  if (!columns.empty()) locate();
  while (pos < bytes.size()) {
    std::size_t nl = bytes.find('\n', pos);
    if (nl == std::string_view::npos) nl = bytes.size();
    std::string_view line = bytes.substr(pos, nl - pos);
    pos = nl + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    split(line, fields);
    if (fields.empty()) continue;
    if (fields[0].front() == '#' || fields[0].substr(0, 2) == "//") {
      // CloudCompare writes its header as a comment: "//X,Y,Z,R,G,B".
      if (columns.empty() && !header_read && fields[0].substr(0, 2) == "//" &&
          fields[0].size() > 2) {
        std::vector<std::string_view> names = fields;
        names[0].remove_prefix(2);
        PointColumns named;
        for (auto n : names) named.push_back(canonical(n));
        if (std::count(named.begin(), named.end(), "x") == 1) {
          check_columns(named, source + ": line " + std::to_string(line_no));
          columns = named;
          locate();
          header_read = true;
        }
      }
      continue;
    }
    const std::string where = "line " + std::to_string(line_no);
    if (pts && !declared) {
      const auto n = number(fields[0]);
      if (fields.size() != 1 || !n || *n < 0 || *n != std::floor(*n))
        throw InputError(source, where + ": a PTS file begins with its point count");
      declared = static_cast<std::uint64_t>(*n);
      // Each point takes at least six characters ("0 0 0\n").
      if (*declared > bytes.size() / 6 + 1)
        throw InputError(source, where + ": " + std::to_string(*declared) +
                                     " points do not fit in the file's " +
                                     std::to_string(bytes.size()) + " bytes");
      out.mesh.vertices.reserve(*declared);
      continue;
    }
    if (!header_read && columns.empty() && !number(fields[0])) {
      PointColumns named;
      for (auto n : fields) named.push_back(canonical(n));
      check_columns(named, source + ": " + where + " (the header)");
      columns = named;
      locate();
      header_read = true;
      continue;
    }
    header_read = true;
    if (columns.empty()) {
      columns = columns_of_count(fields.size(), pts);
      if (columns.empty())
        throw InputError(source, where + ": " + std::to_string(fields.size()) +
                                     " columns and no header naming them: give --columns "
                                     "(e.g. x,y,z,r,g,b)");
      locate();
    }
    if (fields.size() != columns.size())
      throw InputError(source, where + ": " + std::to_string(fields.size()) + " values, " +
                                   std::to_string(columns.size()) + " columns expected");
    values.assign(fields.size(), 0.0);
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (columns[i].empty()) continue;
      const auto v = number(fields[i]);
      if (!v)
        throw InputError(source, where + ": column " + std::to_string(i + 1) + " '" +
                                     std::string(fields[i].substr(0, 40)) + "' is not a number");
      values[i] = *v;
    }
    const Eigen::Vector3d p(values[*x], values[*y], values[*z]);
    require_finite_point(p, source, where);
    out.mesh.vertices.push_back(p);
    if (r) {
      std::array<double, 3> c{values[*r], values[*g], values[*b]};
      for (double v : c) {
        if (!std::isfinite(v) || v < 0 || v > 255)
          throw InputError(source, where + ": a colour value outside 0..255");
        largest_colour = std::max(largest_colour, v);
        fractional_colour = fractional_colour || v != std::floor(v);
      }
      colours.push_back(c);
    }
    if (i) {
      if (!std::isfinite(values[*i]))
        throw InputError(source, where + ": the intensity is not a finite number");
      out.intensities.push_back(static_cast<float>(values[*i]));
    }
    if (nx) {
      const Eigen::Vector3f n(static_cast<float>(values[*nx]), static_cast<float>(values[*ny]),
                              static_cast<float>(values[*nz]));
      if (!n.allFinite()) throw InputError(source, where + ": a normal is not finite");
      out.normals.push_back(n);
    }
  }
  if (declared && *declared != out.mesh.vertices.size())
    throw InputError(source, "the file says " + std::to_string(*declared) + " points and holds " +
                                 std::to_string(out.mesh.vertices.size()));
  if (out.mesh.vertices.empty()) throw InputError(source, "no points in the file");
  const double colour_scale = largest_colour <= 1 && fractional_colour ? 255.0 : 1.0;
  out.mesh.colours.reserve(colours.size());
  for (const auto& c : colours)
    out.mesh.colours.push_back({static_cast<std::uint8_t>(std::lround(c[0] * colour_scale)),
                                static_cast<std::uint8_t>(std::lround(c[1] * colour_scale)),
                                static_cast<std::uint8_t>(std::lround(c[2] * colour_scale))});
  take_datum(out);
  return out;
}

}  // namespace rockface::storage
