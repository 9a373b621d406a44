#include "storage/export_joints_csv.h"

#include <cstdio>

#include "storage/export_file.h"
#include "storage/project_store.h"

namespace rockface::storage {

namespace {

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

std::string number(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", decimals, value);
  return text;
}

}  // namespace

void write_joints_csv(std::ostream& out, const std::vector<Joint>& joints,
                      const Eigen::Vector3d& datum) {
  out << "id,dip,dip_direction,set,x,y,z,visit,source\n";
  for (const auto& j : joints) {
    // Angles to 1e-3 degree and positions to 0.1 mm: finer than any field
    // measurement, so the CSV loses nothing a stereonet program could use.
    out << csv_field(j.label) << ',' << number(j.dip_deg, 3) << ',' << number(j.dipdir_deg, 3)
        << ',' << csv_field(j.set_label) << ',';
    if (j.point) {
      const Eigen::Vector3d p = datum + *j.point;
      out << number(p.x(), 4) << ',' << number(p.y(), 4) << ',' << number(p.z(), 4);
    } else {
      out << ",,";
    }
    out << ',' << j.visit_id << ',' << csv_field(j.source) << '\n';
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
