#include "core/kinematics/effects/effect_shotcrete.h"

#include <cmath>

#include "core/common/error.h"

namespace rockface::kinematics {

double free_face_outline(const blocks::Polyhedron& block) {
  double length = 0;
  const auto& faces = block.faces();
  const auto& planes = block.planes();
  for (const blocks::Edge& e : block.edges()) {
    const auto kl = planes[faces[e.left].plane].kind;
    const auto kr = planes[faces[e.right].plane].kind;
    if ((kl == blocks::PlaneKind::FreeFace) != (kr == blocks::PlaneKind::FreeFace))
      length += (block.vertices()[e.v1] - block.vertices()[e.v0]).norm();
  }
  return length;
}

ShotcreteEffect::ShotcreteEffect(std::string label, double thickness, double shear_strength,
                                 const Eigen::Vector3d& failure_direction)
    : label_(std::move(label)), thickness_(thickness), shear_strength_(shear_strength) {
  if (!(thickness > 0) || !std::isfinite(thickness))
    throw InputError(label_ + ".thickness", "must be a positive number of metres");
  if (!(shear_strength > 0) || !std::isfinite(shear_strength))
    throw InputError(label_ + ".shear_strength", "must be a positive number of pascals");
  const double len = failure_direction.norm();
  if (!(len > 0) || !std::isfinite(len))
    throw InputError(label_, "the block's failure direction is zero: nothing to resist");
  direction_ = failure_direction / len;
}

EffectLoad ShotcreteEffect::load(const blocks::Polyhedron& block,
                                 const blocks::MassProperties& mass) const {
  EffectLoad l;
  double area = 0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (std::size_t f = 0; f < block.faces().size(); ++f) {
    if (block.planes()[block.faces()[f].plane].kind != blocks::PlaneKind::FreeFace) continue;
    const double a = blocks::face_area(block, static_cast<int>(f));
    area += a;
    centre += a * blocks::face_centroid(block, static_cast<int>(f));
  }
  const double outline = free_face_outline(block);
  if (!(area > 0) || !(outline > 0)) {
    l.notes.push_back(label_ + " does not act on block " + block.id() +
                      ": the block has no exposed face to line");
    return l;
  }
  centre /= area;
  l.force = -capacity(outline) * direction_;
  l.moment = (centre - mass.centroid).cross(l.force);
  l.acts = true;
  return l;
}

}  // namespace rockface::kinematics
