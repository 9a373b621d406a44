#include "storage/exchange/export_joints_csv.h"

#include <cmath>
#include <map>

#include "core/common/error.h"

#include "core/common/atomic_file.h"
#include "core/common/number_format.h"
#include "storage/exchange/csv_record.h"
#include "storage/project/project_store.h"

namespace rockface::storage {

std::vector<Joint> read_joints_csv(std::istream& in, const Eigen::Vector3d& datum,
                                   const std::string& where) {
  std::vector<std::string> header, row;
  if (!read_csv_record(in, header)) throw InputError(where, "empty: no header line");
  std::map<std::string, std::size_t> column;
  for (std::size_t i = 0; i < header.size(); ++i) column[header[i]] = i;
  for (const char* needed : {"id", "dip", "dip_direction"})
    if (!column.count(needed))
      throw InputError(where, std::string("no column '") + needed + "' in the header");
  std::vector<Joint> joints;
  for (int line = 2; read_csv_record(in, row); ++line) {
    if (row.size() == 1 && row[0].empty()) continue;  // blank line
    const std::string at = where + ": line " + std::to_string(line);
    auto text = [&](const char* name) -> std::string {
      const auto it = column.find(name);
      return it != column.end() && it->second < row.size() ? row[it->second] : std::string();
    };
    auto number_of = [&](const char* name) -> std::optional<double> {
      const std::string t = text(name);
      if (t.empty()) return std::nullopt;
      std::size_t used = 0;
      double v = 0;
      try {
        v = std::stod(t, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != t.size() || !std::isfinite(v))
        throw InputError(at + ", " + name, "'" + t + "' is not a number");
      return v;
    };
    Joint j;
    j.label = text("id");
    const auto dip = number_of("dip"), dipdir = number_of("dip_direction");
    if (!dip || !dipdir) throw InputError(at, "dip and dip_direction are required");
    if (*dip < 0 || *dip > 90) throw InputError(at + ", dip", "must be in [0, 90]");
    j.dip_deg = *dip;
    j.dipdir_deg = *dipdir;
    j.set_label = text("set");
    const auto x = number_of("x"), y = number_of("y"), z = number_of("z");
    if (x && y && z) j.point = Eigen::Vector3d(*x, *y, *z) - datum;
    j.source = text("source");
    j.type = text("type");
    j.persistence_m = number_of("persistence");
    joints.push_back(std::move(j));
  }
  return joints;
}

void write_joints_csv(std::ostream& out, const std::vector<Joint>& joints,
                      const Eigen::Vector3d& datum) {
  out << "id,dip,dip_direction,set,x,y,z,visit,source,type,persistence\n";
  for (const auto& j : joints) {
    // Angles to 1e-3 degree and positions to 0.1 mm: finer than any field
    // measurement, so the CSV loses nothing a stereonet program could use.
    out << csv_field(j.label) << ',' << format_fixed(j.dip_deg, 3) << ','
        << format_fixed(j.dipdir_deg, 3) << ',' << csv_field(j.set_label) << ',';
    if (j.point) {
      const Eigen::Vector3d p = datum + *j.point;
      out << format_fixed(p.x(), 4) << ',' << format_fixed(p.y(), 4) << ','
          << format_fixed(p.z(), 4);
    } else {
      out << ",,";
    }
    out << ',' << j.visit_id << ',' << csv_field(j.source) << ',' << csv_field(j.type) << ',';
    if (j.persistence_m) out << format_fixed(*j.persistence_m, 3);
    out << '\n';
  }
}

std::size_t export_joints_csv(ProjectStore& store, const std::filesystem::path& file,
                              std::optional<RecordId> visit_id) {
  const auto joints = store.list_joints(visit_id);
  const Eigen::Vector3d datum = store.project().datum;
  write_file_atomically(file, [&](std::ostream& out) { write_joints_csv(out, joints, datum); });
  if (!store.read_only())
    store.log_action(visit_id, "export joints csv",
                     file.string() + ": " + std::to_string(joints.size()) + " joints");
  return joints.size();
}

}  // namespace rockface::storage
