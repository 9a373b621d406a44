#pragma once
// Ground control for a cloud in a local frame (`rockface import --frame
// local --gcp FILE`): the points are picked on the import's virtual view, as
// `replay --gcp` takes them on the left photograph (CSV id,u,v,X,Y,Z, u and v
// the view's pixels, X Y Z survey coordinates); each pick is the surface
// point under its pixel nearest the view's camera, and the cloud is scaled,
// levelled and turned onto the survey by the similarity of the picks
// (core/photogrammetry/estimators/registration.h), as a photographed visit
// is.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/photogrammetry/estimators/registration.h"

namespace rockface::app {

// vertices: the cloud's stored (local) frame; pixels: each vertex's pixel in
// the view; camera_centre: the view's, in the same frame. Throws InputError
// naming the file and the point: fewer than three points, a pixel on no
// triangle, points on a line.
photogrammetry::ControlPointRegistration register_import_to_control(
    const std::string& gcp_file, const std::vector<Eigen::Vector3d>& vertices,
    const std::vector<std::array<int, 3>>& triangles, const std::vector<Eigen::Vector2f>& pixels,
    const Eigen::Vector3d& camera_centre);

}  // namespace rockface::app
