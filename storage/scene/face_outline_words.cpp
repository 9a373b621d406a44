#include "storage/scene/face_outline_words.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>

#include "core/common/number_format.h"

namespace rockface::storage {

namespace {

constexpr double kWordsPi = 3.14159265358979323846;

// The upward unit normal of a plane given by dip and dip direction (deg).
std::array<double, 3> plane_normal_of(double dip_deg, double dipdir_deg) {
  const double d = dip_deg * kWordsPi / 180, a = dipdir_deg * kWordsPi / 180;
  return {std::sin(d) * std::sin(a), std::sin(d) * std::cos(a), std::cos(d)};
}

double angle_between_deg(const Measurement& a, const Measurement& b) {
  const auto u = plane_normal_of(*a.dip_deg, *a.dipdir_deg),
             v = plane_normal_of(*b.dip_deg, *b.dipdir_deg);
  const double c = std::min(1.0, std::abs(u[0] * v[0] + u[1] * v[1] + u[2] * v[2]));
  return std::acos(c) * 180 / kWordsPi;
}

}  // namespace

bool is_face_outline(const Measurement& m, const std::vector<Joint>& joints) {
  if (m.kind != Measurement::Kind::area || !m.rock_side.empty()) return false;
  return std::none_of(joints.begin(), joints.end(),
                      [&](const Joint& j) { return j.source == "area " + m.label; });
}

std::string outline_of_piece(const std::string& label) {
  // A piece's letter follows the outline's number: "F1a".
  if (label.size() >= 3 && label.back() >= 'a' && label.back() <= 'z' &&
      std::isdigit(static_cast<unsigned char>(label[label.size() - 2])))
    return label.substr(0, label.size() - 1);
  return label;
}

std::vector<std::string> face_outline_words(const std::vector<Measurement>& measurements,
                                            const std::vector<Joint>& joints) {
  std::vector<std::string> names;
  std::vector<std::vector<const Measurement*>> pieces;
  for (const auto& m : measurements) {
    if (!is_face_outline(m, joints)) continue;
    const std::string name = outline_of_piece(m.label);
    const auto at = std::find(names.begin(), names.end(), name);
    if (at == names.end()) {
      names.push_back(name);
      pieces.push_back({&m});
    } else {
      pieces[static_cast<std::size_t>(at - names.begin())].push_back(&m);
    }
  }
  std::vector<std::string> out;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const auto& p = pieces[k];
    std::string line = "face outline " + names[k] + ": ";
    line += p.size() == 1 ? "one flat piece" : std::to_string(p.size()) + " flat pieces";
    double apart = 0;
    bool known = true;
    for (std::size_t i = 0; i < p.size(); ++i) {
      known = known && p[i]->dip_deg && p[i]->dipdir_deg;
      for (std::size_t j = 0; known && j < i; ++j)
        if (p[j]->dip_deg && p[j]->dipdir_deg)
          apart = std::max(apart, angle_between_deg(*p[i], *p[j]));
    }
    if (p.size() == 2 && known)
      line += ", " + format_fixed(apart, 1) + "° apart";
    else if (p.size() > 2 && known)
      line += ", bending up to " + format_fixed(apart, 1) + "°";
    line += ", RMS ";
    for (std::size_t i = 0; i < p.size(); ++i)
      line += (i ? " / " : "") + format_fixed(p[i]->fit_rms_m * 1000, 0) + " mm";
    std::vector<std::string> notes;
    for (const auto* m : p)
      if (!m->note.empty() && std::find(notes.begin(), notes.end(), m->note) == notes.end())
        notes.push_back(m->note);
    for (const auto& n : notes) line += "; " + n;
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace rockface::storage
