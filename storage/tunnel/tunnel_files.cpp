#include "storage/tunnel/tunnel_files.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "storage/json_reader.h"
#include "storage/tunnel/built_alignment.h"

namespace rockface::storage {

namespace {

constexpr double kDeg = std::numbers::pi / 180;

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), "cannot be read (missing or not permitted)");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string trim(std::string s) {
  auto sp = [](unsigned char c) { return std::isspace(c) != 0; };
  while (!s.empty() && sp(static_cast<unsigned char>(s.back()))) s.pop_back();
  std::size_t i = 0;
  while (i < s.size() && sp(static_cast<unsigned char>(s[i]))) ++i;
  s = s.substr(i);
  // A field quoted by a spreadsheet.
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
  return s;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// A CSV table: its header and rows with their line numbers. Lines starting
// with '#' and blank lines are skipped; the separator is ';' when the header
// has one and no ',' (a European spreadsheet), else ','.
struct Csv {
  std::string source;
  std::vector<std::string> header;
  int header_line = 0;
  struct Row {
    int line = 0;
    std::vector<std::string> fields;
  };
  std::vector<Row> rows;

  std::string where(int line) const { return source + ":" + std::to_string(line); }
  std::string where(int line, const std::string& field) const {
    return where(line) + ", field '" + field + "'";
  }
};

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    if (c == sep && !quoted) {
      out.push_back(trim(cur));
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(trim(cur));
  return out;
}

Csv read_csv(const std::string& text, const std::string& source) {
  Csv csv;
  csv.source = source;
  std::istringstream in(text);
  std::string line;
  int number = 0;
  char sep = ',';
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line = line.substr(3);  // UTF-8 BOM
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    if (csv.header.empty()) {
      if (t.find(';') != std::string::npos && t.find(',') == std::string::npos) sep = ';';
      csv.header = split(t, sep);
      for (auto& h : csv.header) h = lower(h);
      csv.header_line = number;
      continue;
    }
    csv.rows.push_back({number, split(line, sep)});
  }
  if (csv.header.empty()) throw InputError(source, "is empty: no header row");
  return csv;
}

double number_field(const Csv& csv, const Csv::Row& row, std::size_t col, const std::string& name) {
  const std::string& f = row.fields[col];
  if (f.empty()) throw InputError(csv.where(row.line, name), "is empty");
  double v = 0;
  const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
  if (ec != std::errc() || end != f.data() + f.size())
    throw InputError(csv.where(row.line, name), "'" + f + "' is not a number");
  if (!std::isfinite(v)) throw InputError(csv.where(row.line, name), "must be finite");
  return v;
}

// Column index of each wanted name (aliases allowed), refusing duplicates.
std::map<std::string, std::size_t> columns(const Csv& csv,
                                           const std::map<std::string, std::string>& alias) {
  std::map<std::string, std::size_t> at;
  for (std::size_t i = 0; i < csv.header.size(); ++i) {
    auto it = alias.find(csv.header[i]);
    if (it == alias.end()) continue;  // an extra column (a remark, a point id): ignored
    if (at.count(it->second))
      throw InputError(csv.where(csv.header_line),
                       "the column '" + it->second + "' is given twice");
    at[it->second] = i;
  }
  return at;
}

void require_field_count(const Csv& csv, const Csv::Row& row) {
  if (row.fields.size() != csv.header.size())
    throw InputError(csv.where(row.line), "expected " + std::to_string(csv.header.size()) +
                                              " fields as in the header, got " +
                                              std::to_string(row.fields.size()));
}

// An error of the alignment names stations[i]: put the file and line in front.
[[noreturn]] void rethrow_at_line(const InputError& e, const std::string& source,
                                  const std::vector<int>& line_of) {
  std::smatch m;
  const std::string where = e.where();
  if (!source.empty() && std::regex_search(where, m, std::regex(R"(stations\[(\d+)\])"))) {
    const std::size_t i = std::stoul(m[1].str());
    if (i < line_of.size())
      throw InputError(source + ":" + std::to_string(line_of[i]) + " (" + where + ")", e.reason());
  }
  throw InputError(source.empty() ? where : source + ": " + where, e.reason());
}

}  // namespace

// ---------------------------------------------------------------- alignment

tunnel::Alignment AlignmentTable::build(const Eigen::Vector3d& datum, tunnel::Drive drive) const {
  try {
    // Kept for the process: the table's check below and its uses after are
    // one build per datum (built_alignment.h).
    return built_alignment(stations, radii, polyline, drive, datum);
  } catch (const InputError& e) {
    rethrow_at_line(e, source, line_of);
  }
}

AlignmentTable parse_alignment_csv(const std::string& text, const std::string& source) {
  const Csv csv = read_csv(text, source);
  const auto at = columns(csv, {{"chainage", "chainage"},
                                {"station", "chainage"},
                                {"easting", "easting"},
                                {"east", "easting"},
                                {"northing", "northing"},
                                {"north", "northing"},
                                {"elevation", "elevation"},
                                {"elev", "elevation"},
                                {"height", "elevation"},
                                {"radius", "radius"}});
  for (const char* need : {"chainage", "easting", "northing", "elevation"})
    if (!at.count(need))
      throw InputError(csv.where(csv.header_line),
                       std::string("the header has no column '") + need +
                           "' (wanted: chainage,easting,northing,elevation[,radius])");
  AlignmentTable table;
  table.source = source;
  table.polyline = !at.count("radius");
  for (const auto& row : csv.rows) {
    require_field_count(csv, row);
    tunnel::AlignmentStation s;
    s.chainage = number_field(csv, row, at.at("chainage"), "chainage");
    s.survey = {number_field(csv, row, at.at("easting"), "easting"),
                number_field(csv, row, at.at("northing"), "northing"),
                number_field(csv, row, at.at("elevation"), "elevation")};
    table.stations.push_back(s);
    table.line_of.push_back(row.line);
    if (!table.polyline) {
      const std::size_t c = at.at("radius");
      table.radii.push_back(row.fields[c].empty() ? 0.0 : number_field(csv, row, c, "radius"));
    }
  }
  if (table.stations.size() < 2)
    throw InputError(source, "an alignment needs at least two stations, the file has " +
                                 std::to_string(table.stations.size()));
  if (!table.polyline) {
    if (table.radii.back() != 0)
      throw InputError(csv.where(table.line_of.back(), "radius"),
                       "the last station starts no element: its radius must be empty or 0");
    table.radii.pop_back();
  }
  // Checks order, duplicates, element lengths and radii now (the datum does
  // not change them): a bad table is refused when read, not when used.
  table.build(table.stations.front().survey, tunnel::Drive::ascending);
  return table;
}

AlignmentTable read_alignment_csv(const std::filesystem::path& file) {
  return parse_alignment_csv(read_text(file), file.string());
}

std::string alignment_csv_text(const AlignmentTable& table) {
  std::ostringstream out;
  out << (table.polyline ? "chainage,easting,northing,elevation\n"
                         : "chainage,easting,northing,elevation,radius\n");
  for (std::size_t i = 0; i < table.stations.size(); ++i) {
    const auto& s = table.stations[i];
    out << format_round_trip(s.chainage) << ',' << format_round_trip(s.survey.x()) << ','
        << format_round_trip(s.survey.y()) << ',' << format_round_trip(s.survey.z());
    if (!table.polyline)
      out << ',' << (i < table.radii.size() ? format_round_trip(table.radii[i]) : "");
    out << '\n';
  }
  return out.str();
}

// ---------------------------------------------------------------- profile, JSON

namespace {

constexpr const char* kProfileFormat = "rockface-tunnel-profile/1";

// Segment i of a validated chain is segment i of the file unless the chain
// was given clockwise and turned round (DesignProfile's constructor).
std::size_t index_in_file(const tunnel::DesignProfile& p,
                          const std::vector<tunnel::ProfileSegment>& given, std::size_t i) {
  const bool reversed = (p.segments().front().to - given.front().to).norm() > 0;
  return reversed ? given.size() - 1 - i : i;
}

tunnel::DesignProfile checked(const std::vector<tunnel::ProfileSegment>& given,
                              std::optional<Eigen::Vector2d> centre, const std::string& name,
                              const std::string& source) {
  tunnel::DesignProfile p(given, centre, name);
  const tunnel::ProfileCheck c = p.validate();
  if (!c.ok)
    throw InputError(c.segment ? source + ": segments[" +
                                     std::to_string(index_in_file(p, given, *c.segment)) + "]"
                               : source,
                     c.message);
  return p;
}

Eigen::Vector2d uv(const Reader& r, const nlohmann::json& v, const std::string& path) {
  if (!v.is_array() || v.size() != 2) r.fail(path, "must be [u, v] (metres)");
  return {r.number(v[0], path + "[0]"), r.number(v[1], path + "[1]")};
}

}  // namespace

tunnel::DesignProfile parse_profile_json(const std::string& text, const std::string& source) {
  const Reader r(source);
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::out_of_range&) {
    throw_number_overflow(text, source);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(source, std::string("is not valid JSON: ") + e.what());
  }
  if (!doc.is_object()) r.fail("(top level)", "must be an object with \"segments\"");
  r.only_fields(doc, "", {"format", "name", "ray_centre", "segments"});
  if (const auto* f = r.optional(doc, "", "format")) {
    if (!f->is_string() || f->get<std::string>() != kProfileFormat)
      r.fail("format", std::string("must be \"") + kProfileFormat + "\"");
  }
  std::string name;
  if (const auto* n = r.optional(doc, "", "name")) {
    if (!n->is_string()) r.fail("name", "must be text");
    name = n->get<std::string>();
  }
  std::optional<Eigen::Vector2d> centre;
  if (const auto* c = r.optional(doc, "", "ray_centre")) centre = uv(r, *c, "ray_centre");
  const auto& segs = r.require(doc, "", "segments");
  if (!segs.is_array() || segs.empty()) r.fail("segments", "must be a non-empty array");
  std::vector<tunnel::ProfileSegment> out;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const std::string path = "segments[" + std::to_string(i) + "]";
    const auto& s = segs[i];
    if (!s.is_object() || s.size() != 1)
      r.fail(path, "must be {\"line\": {...}} or {\"arc\": {...}}");
    if (s.contains("line")) {
      const auto& l = s["line"];
      r.only_fields(l, path + ".line", {"from", "to"});
      out.push_back(tunnel::ProfileSegment::line(
          uv(r, r.require(l, path + ".line", "from"), path + ".line.from"),
          uv(r, r.require(l, path + ".line", "to"), path + ".line.to")));
    } else if (s.contains("arc")) {
      const auto& a = s["arc"];
      const std::string ap = path + ".arc";
      if (!a.is_object()) r.fail(ap, "must be an object");
      if (a.contains("radius")) {
        r.only_fields(a, ap, {"centre", "radius", "start_deg", "end_deg"});
        const Eigen::Vector2d c = uv(r, r.require(a, ap, "centre"), ap + ".centre");
        const double radius = r.positive(r.require(a, ap, "radius"), ap + ".radius");
        const double from = r.number(r.require(a, ap, "start_deg"), ap + ".start_deg");
        const double to = r.number(r.require(a, ap, "end_deg"), ap + ".end_deg");
        if (from == to) r.fail(ap + ".end_deg", "equals start_deg: the arc has no length");
        out.push_back(tunnel::ProfileSegment::arc_polar(c, radius, from * kDeg, to * kDeg));
      } else {
        r.only_fields(a, ap, {"from", "to", "centre", "sense"});
        bool ccw = true;
        if (const auto* sense = r.optional(a, ap, "sense")) {
          if (!sense->is_string() || (*sense != "ccw" && *sense != "cw"))
            r.fail(ap + ".sense", "must be \"ccw\" or \"cw\"");
          ccw = *sense == "ccw";
        }
        out.push_back(tunnel::ProfileSegment::arc(uv(r, r.require(a, ap, "from"), ap + ".from"),
                                                  uv(r, r.require(a, ap, "to"), ap + ".to"),
                                                  uv(r, r.require(a, ap, "centre"), ap + ".centre"),
                                                  ccw));
      }
    } else {
      r.fail(path, "must be {\"line\": {...}} or {\"arc\": {...}}");
    }
  }
  return checked(out, centre, name, source);
}

tunnel::DesignProfile read_profile_json(const std::filesystem::path& file) {
  return parse_profile_json(read_text(file), file.string());
}

std::string profile_json_text(const tunnel::DesignProfile& profile) {
  nlohmann::json doc;
  doc["format"] = kProfileFormat;
  doc["name"] = profile.name();
  if (profile.ray_centre_given())
    doc["ray_centre"] = {profile.ray_centre().x(), profile.ray_centre().y()};
  doc["segments"] = nlohmann::json::array();
  for (const auto& s : profile.segments()) {
    if (s.kind == tunnel::ProfileSegment::Kind::line) {
      doc["segments"].push_back(
          {{"line", {{"from", {s.from.x(), s.from.y()}}, {"to", {s.to.x(), s.to.y()}}}}});
    } else {
      doc["segments"].push_back({{"arc",
                                  {{"from", {s.from.x(), s.from.y()}},
                                   {"to", {s.to.x(), s.to.y()}},
                                   {"centre", {s.centre.x(), s.centre.y()}},
                                   {"sense", s.ccw ? "ccw" : "cw"}}}});
    }
  }
  return doc.dump(2) + "\n";
}

// ---------------------------------------------------------------- profile, CSV

tunnel::DesignProfile parse_profile_csv(const std::string& text, const std::string& source) {
  const Csv csv = read_csv(text, source);
  const auto at = columns(csv, {{"kind", "kind"},
                                {"from_u", "from_u"},
                                {"from_v", "from_v"},
                                {"to_u", "to_u"},
                                {"to_v", "to_v"},
                                {"centre_u", "centre_u"},
                                {"centre_v", "centre_v"},
                                {"sense", "sense"}});
  for (const char* need : {"kind", "from_u", "from_v", "to_u", "to_v", "centre_u", "centre_v"})
    if (!at.count(need))
      throw InputError(csv.where(csv.header_line),
                       std::string("the header has no column '") + need +
                           "' (wanted: kind,from_u,from_v,to_u,to_v,centre_u,centre_v,sense)");
  std::vector<tunnel::ProfileSegment> segs;
  std::optional<Eigen::Vector2d> centre;
  auto field = [&](const Csv::Row& row, const char* name) -> const std::string& {
    return row.fields[at.at(name)];
  };
  auto num = [&](const Csv::Row& row, const char* name) {
    return number_field(csv, row, at.at(name), name);
  };
  for (const auto& row : csv.rows) {
    require_field_count(csv, row);
    const std::string kind = lower(field(row, "kind"));
    if (kind == "ray_centre") {
      if (centre) throw InputError(csv.where(row.line, "kind"), "a second ray_centre row");
      centre = Eigen::Vector2d(num(row, "centre_u"), num(row, "centre_v"));
      continue;
    }
    const Eigen::Vector2d from(num(row, "from_u"), num(row, "from_v"));
    const Eigen::Vector2d to(num(row, "to_u"), num(row, "to_v"));
    if (kind == "line") {
      for (const char* unused : {"centre_u", "centre_v"})
        if (!field(row, unused).empty())
          throw InputError(csv.where(row.line, unused), "a line has no centre: leave it empty");
      segs.push_back(tunnel::ProfileSegment::line(from, to));
    } else if (kind == "arc") {
      const Eigen::Vector2d c(num(row, "centre_u"), num(row, "centre_v"));
      bool ccw = true;
      if (at.count("sense")) {
        const std::string sense = lower(field(row, "sense"));
        if (sense != "" && sense != "ccw" && sense != "cw")
          throw InputError(csv.where(row.line, "sense"),
                           "must be ccw, cw or empty (ccw), not '" + field(row, "sense") + "'");
        ccw = sense != "cw";
      }
      segs.push_back(tunnel::ProfileSegment::arc(from, to, c, ccw));
    } else {
      throw InputError(csv.where(row.line, "kind"),
                       "must be line, arc or ray_centre, not '" + field(row, "kind") + "'");
    }
  }
  if (segs.empty()) throw InputError(source, "has no segments");
  // Validation names the segment; add its line in the file.
  const tunnel::DesignProfile p(segs, centre);
  const tunnel::ProfileCheck c = p.validate();
  if (!c.ok) {
    std::string where = source;
    if (c.segment) {
      std::vector<int> lines;
      for (const auto& row : csv.rows)
        if (lower(field(row, "kind")) != "ray_centre") lines.push_back(row.line);
      const std::size_t i = index_in_file(p, segs, *c.segment);
      where = csv.where(lines[std::min(i, lines.size() - 1)]) + " (segments[" + std::to_string(i) +
              "])";
    }
    throw InputError(where, c.message);
  }
  return p;
}

tunnel::DesignProfile read_profile_csv(const std::filesystem::path& file) {
  return parse_profile_csv(read_text(file), file.string());
}

std::string profile_csv_text(const tunnel::DesignProfile& profile) {
  std::ostringstream out;
  out << "kind,from_u,from_v,to_u,to_v,centre_u,centre_v,sense\n";
  for (const auto& s : profile.segments()) {
    const bool arc = s.kind == tunnel::ProfileSegment::Kind::arc;
    out << (arc ? "arc," : "line,") << format_round_trip(s.from.x()) << ','
        << format_round_trip(s.from.y()) << ',' << format_round_trip(s.to.x()) << ','
        << format_round_trip(s.to.y()) << ',';
    if (arc)
      out << format_round_trip(s.centre.x()) << ',' << format_round_trip(s.centre.y()) << ','
          << (s.ccw ? "ccw" : "cw");
    else
      out << ",,";
    out << '\n';
  }
  if (profile.ray_centre_given())
    out << "ray_centre,,,,," << format_round_trip(profile.ray_centre().x()) << ','
        << format_round_trip(profile.ray_centre().y()) << ",\n";
  return out.str();
}

tunnel::DesignProfile read_profile_file(const std::filesystem::path& file) {
  const std::string ext = lower(file.extension().string());
  if (ext == ".json") return read_profile_json(file);
  if (ext == ".csv") return read_profile_csv(file);
  throw InputError(file.string(), "a design profile is a .json or a .csv file");
}

}  // namespace rockface::storage
