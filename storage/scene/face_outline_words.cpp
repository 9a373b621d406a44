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

namespace {

// The outlines among `measurements` in their order: each its name and pieces.
struct Outline {
  std::string name;
  std::vector<const Measurement*> pieces;
};

std::vector<Outline> outlines_of(const std::vector<Measurement>& measurements,
                                 const std::vector<Joint>& joints) {
  std::vector<Outline> out;
  for (const auto& m : measurements) {
    if (!is_face_outline(m, joints)) continue;
    const std::string name = outline_of_piece(m.label);
    const auto at =
        std::find_if(out.begin(), out.end(), [&](const Outline& o) { return o.name == name; });
    if (at == out.end())
      out.push_back({name, {&m}});
    else
      at->pieces.push_back(&m);
  }
  return out;
}

std::string outline_line(const Outline& o) {
  const auto& p = o.pieces;
  std::string line = "face outline " + o.name + ": ";
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
  return line;
}

// One flat piece and nothing noted: what most outlines of a face are.
bool one_plain_piece(const Outline& o) {
  return o.pieces.size() == 1 && o.pieces[0]->note.empty();
}

}  // namespace

std::vector<std::string> face_outline_words(const std::vector<Measurement>& measurements,
                                            const std::vector<Joint>& joints) {
  std::vector<std::string> out;
  for (const auto& o : outlines_of(measurements, joints)) out.push_back(outline_line(o));
  return out;
}

std::vector<std::string> face_outline_summary(const std::vector<Measurement>& measurements,
                                              const std::vector<Joint>& joints) {
  const std::vector<Outline> all = outlines_of(measurements, joints);
  std::vector<std::string> out;
  std::string names;
  int count = 0;
  double worst_rms_m = 0;
  for (const auto& o : all)
    if (one_plain_piece(o)) {
      names += (names.empty() ? "" : ", ") + o.name;
      worst_rms_m = std::max(worst_rms_m, o.pieces[0]->fit_rms_m);
      ++count;
    }
  if (count == 1)
    out.push_back(outline_line(*std::find_if(all.begin(), all.end(), one_plain_piece)));
  else if (count > 1)
    out.push_back(std::to_string(count) + " face outlines, each one flat piece (" + names +
                  "), RMS at most " + format_fixed(worst_rms_m * 1000, 0) + " mm");
  for (const auto& o : all)
    if (!one_plain_piece(o)) out.push_back(outline_line(o));
  return out;
}

}  // namespace rockface::storage
