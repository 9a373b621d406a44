#include "core/kinematics/joint_pyramids.h"

#include <algorithm>
#include <stdexcept>

#include "core/common/error.h"

namespace rockface::kinematics {

geometry::Cone excavation_pyramid(const std::vector<FreeFaceSpec>& faces) {
  geometry::Cone ep;
  for (const auto& f : faces) ep.add(geometry::side_sign(f.rock_side) * f.normal);
  return ep;
}

geometry::Cone joint_pyramid(const std::vector<JointSpec>& joints,
                             const std::vector<geometry::HalfSpace>& code) {
  geometry::Cone jp;
  for (size_t i = 0; i < joints.size(); ++i)
    if (code[i] != geometry::HalfSpace::NotInvolved)
      jp.add(geometry::side_sign(code[i]) * joints[i].normal);
  return jp;
}

PyramidVerdict analyse_joint_pyramid(const std::vector<JointSpec>& joints,
                                     const std::vector<geometry::HalfSpace>& code,
                                     const geometry::Cone& excavation,
                                     const PyramidOptions& options) {
  if (code.size() != joints.size())
    throw std::invalid_argument("pyramid code length differs from the number of joints");
  PyramidVerdict v;
  v.code = code;
  for (auto h : code) v.code_text += geometry::code_digit(h);
  const geometry::Cone jp = joint_pyramid(joints, code);
  v.jp_margin = jp.margin().angle;
  v.jp_ep_margin = jp.intersect(excavation).margin().angle;
  v.empty = !(v.jp_margin > 0);
  v.finite = !(v.jp_ep_margin > 0);
  // Removable needs both: JP open and JP cap EP shut; the verdict is as firm
  // as the weaker of the two.
  v.removable = geometry::decide(std::min(v.jp_margin, -v.jp_ep_margin), options.uncertainty);
  // The mode is given for removable pyramids and for marginal ones (how the
  // block would move if it can), so that rounding on a marginal verdict
  // never decides whether a mode is reported.
  if ((v.removable.value || v.removable.marginal) && !v.empty &&
      options.resultant.squaredNorm() > 0) {
    std::vector<ContactPlane> contacts;
    for (size_t i = 0; i < joints.size(); ++i)
      if (code[i] != geometry::HalfSpace::NotInvolved)
        contacts.push_back({static_cast<int>(i), geometry::side_sign(code[i]) * joints[i].normal,
                            joints[i].friction, 0});
    v.mode = sliding_mode(options.resultant, contacts, options.uncertainty);
  }
  return v;
}

std::vector<PyramidVerdict> analyse_joint_pyramids(const std::vector<JointSpec>& joints,
                                                   const geometry::Cone& excavation,
                                                   const PyramidOptions& options) {
  if (joints.size() > 20)
    throw InputError("joints",
                     "more than 20 joints make more than 2^20 pyramids, which would not "
                     "fit in memory: give the joint sets' mean planes instead");
  const size_t n = joints.size();
  std::vector<PyramidVerdict> out;
  out.reserve(size_t{1} << n);
  std::vector<geometry::HalfSpace> code(n);
  // Codes in numeric order of their digit strings: "000", "001", ...
  for (size_t bits = 0; bits < (size_t{1} << n); ++bits) {
    for (size_t i = 0; i < n; ++i)
      code[i] =
          ((bits >> (n - 1 - i)) & 1) ? geometry::HalfSpace::Lower : geometry::HalfSpace::Upper;
    out.push_back(analyse_joint_pyramid(joints, code, excavation, options));
  }
  return out;
}

}  // namespace rockface::kinematics
