#pragma once
// Triangulation of faces without new vertices: ear clipping in the face's
// plane, so non-convex faces are split into triangles that keep the face's
// orientation (counter-clockwise seen from outside).
#include <array>
#include <vector>

#include "core/blocks/polyhedron.h"

namespace rockface::blocks {

using Triangle = std::array<int, 3>;  // vertex indices, counter-clockwise seen from outside

// n - 2 triangles of face f (n corners). Throws rockface::Error if the loop
// cannot be clipped (a self-intersecting polygon).
std::vector<Triangle> triangulate_face(const Polyhedron& block, int f);

// The triangles of every face; face_of[k] is the face of triangle k.
struct Triangulation {
  std::vector<Triangle> triangles;
  std::vector<int> face_of;
};
Triangulation triangulate(const Polyhedron& block);

}  // namespace rockface::blocks
