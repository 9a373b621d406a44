#include "storage/exchange/traces_csv.h"

#include <map>
#include <string>

#include "core/common/number_format.h"
#include "storage/exchange/csv_record.h"

namespace rockface::storage {

namespace {

// Angles to 1e-3 degree, lengths to 1 mm and positions to 0.1 mm: finer than
// any field measurement, so the CSV loses nothing Dips could use.
void write_trace_point(std::ostream& out, const Eigen::Vector3d& p) {
  out << ',' << format_fixed(p.x(), 4) << ',' << format_fixed(p.y(), 4) << ','
      << format_fixed(p.z(), 4);
}

// The point halfway along the polyline (not the mean of its points, which
// a densely picked end would pull towards it).
Eigen::Vector3d trace_middle(const std::vector<Eigen::Vector3d>& points) {
  double total = 0;
  for (std::size_t i = 1; i < points.size(); ++i) total += (points[i] - points[i - 1]).norm();
  double walked = 0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const double step = (points[i] - points[i - 1]).norm();
    if (step > 0 && walked + step >= total / 2)
      return points[i - 1] + (points[i] - points[i - 1]) * ((total / 2 - walked) / step);
    walked += step;
  }
  return points.front();
}

}  // namespace

std::size_t write_traces_csv(std::ostream& out, const std::vector<Measurement>& measurements,
                             const std::vector<Joint>& joints, const Eigen::Vector3d& datum) {
  std::map<std::string, std::string> set_of_joint;
  for (const auto& j : joints) set_of_joint[j.label] = j.set_label;
  out << "id,dip,dip_direction,set,joint,trace_length_m,censored,x,y,z,x_from,y_from,z_from,x_to,"
         "y_to,z_to,origin,visit\n";
  std::size_t rows = 0;
  for (const auto& m : measurements) {
    if (m.kind != Measurement::Kind::trace || m.points.empty()) continue;
    const auto set = set_of_joint.find(m.joint_label);
    out << csv_field(m.label) << ',' << (m.dip_deg ? format_fixed(*m.dip_deg, 3) : "") << ','
        << (m.dipdir_deg ? format_fixed(*m.dipdir_deg, 3) : "") << ','
        << csv_field(set == set_of_joint.end() ? std::string() : set->second) << ','
        << csv_field(m.joint_label) << ','
        << (m.trace_length_m ? format_fixed(*m.trace_length_m, 3) : "") << ','
        << (m.censored ? "yes" : "no");
    write_trace_point(out, datum + trace_middle(m.points));
    write_trace_point(out, datum + m.points.front());
    write_trace_point(out, datum + m.points.back());
    out << ',' << csv_field(m.origin) << ',' << m.visit_id << '\n';
    ++rows;
  }
  return rows;
}

}  // namespace rockface::storage
