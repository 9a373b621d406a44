#pragma once
// What the readers of a block verdict (the tablet's Blocks screen, the field
// report) ask of a ReportBlock besides its fields: its points in the project
// frame and two answers its parts give together. Functions of the one
// verdict type, so that no reader keeps a copy of it.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/analysis/report.h"

namespace rockface::analysis {

// The vertices are the block's loop on the free surface (a trace block with
// no finite corners, or not one polyhedron; analyse_traces.cpp notes it so),
// not its corners.
bool vertices_are_surface_loop(const ReportBlock& block);

// A corner or an edge of the block can rotate; none when rotation was not
// analysed.
std::optional<bool> can_rotate(const ReportBlock& block);

// The report's absolute points less the project's datum: the project frame
// the 3D image and the face picture are drawn in.
std::vector<Eigen::Vector3d> relative_to(const std::vector<Eigen::Vector3d>& points,
                                         const Eigen::Vector3d& datum);
// The motion's points (path, landing, floor) likewise; the rest as it is.
ReportDynamics relative_to(const ReportDynamics& dynamics, const Eigen::Vector3d& datum);

}  // namespace rockface::analysis
