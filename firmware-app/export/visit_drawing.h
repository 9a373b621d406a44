#pragma once
// What a visit's DXF holds (AutoCAD, Civil 3D): the traces as 3D polylines
// on a layer per joint set, the joints as discs in their planes on a layer
// per set, the blocks as closed polyface meshes on a layer per verdict
// (core/analysis/block_verdict.h), the design profile and the measured
// cross-sections of the round. Absolute survey coordinates (the project's
// datum added back).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/analysis/report.h"
#include "firmware-app/tunnel/visit_profile.h"
#include "storage/exchange/dxf_drawing.h"
#include "storage/project/project_records.h"

namespace rockface::app {

// Layer names: TRACES_<set>, JOINTS_<set> (UNASSIGNED without one),
// BLOCKS_<verdict> (MOVES, MARGINAL, HOLDS, KEYED, NOT_FINITE),
// PROFILE_DESIGN, PROFILE_MEASURED.
std::string set_layer(const std::string& prefix, const std::string& set_label);
std::string verdict_layer(const analysis::ReportBlock& block);

// Each returns how many entities it added; `notes` gets what was left out and why.
std::size_t add_traces(storage::DxfDrawing& drawing,
                       const std::vector<storage::Measurement>& measurements,
                       const std::vector<storage::Joint>& joints, const Eigen::Vector3d& datum,
                       std::vector<std::string>& notes);

// A disc of the joint's persistence (as measured, else its longest trace,
// else its set's mean trace length, else 1 m, said in a note) about its point.
std::size_t add_joint_discs(storage::DxfDrawing& drawing, const std::vector<storage::Joint>& joints,
                            const std::vector<storage::JointSet>& sets,
                            const std::vector<storage::Measurement>& measurements,
                            const Eigen::Vector3d& datum, std::vector<std::string>& notes);

// Blocks as closed meshes from their reported faces (a convex block stored
// before faces were reported: the hull of its corners); a block reported by
// its loop on the free surface, or a non-convex one without faces, is left
// out with a note.
std::size_t add_blocks(storage::DxfDrawing& drawing,
                       const std::vector<analysis::ReportBlock>& blocks,
                       std::vector<std::string>& notes);

// The design outline and the measured outline at every cross-section of the
// round; a measured outline is broken where the 3D image did not see the
// wall (never bridged).
std::size_t add_profile(storage::DxfDrawing& drawing, const VisitProfile& profile,
                        const Eigen::Vector3d& datum, std::vector<std::string>& notes);

}  // namespace rockface::app
