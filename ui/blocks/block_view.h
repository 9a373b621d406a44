#pragma once
// One analysed block as the Blocks screen and the model view show it: the
// stored key columns, what the table needs from the block's report JSON
// (margin, rotatability, vertices) and one verdict that picks its colour.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/analysis/report.h"
#include "storage/project/project_records.h"
#include "ui/blocks/block_verdict.h"

namespace rockface::ui {

struct BlockView {
  std::string label, source, code, mode;
  bool finite = false, removable = false, marginal = false;
  std::optional<double> fos;
  std::optional<double> margin_deg;
  std::optional<bool> rotatable;          // a corner or edge can rotate; absent: not analysed
  std::vector<Eigen::Vector3d> vertices;  // project frame (datum-relative)
  // The vertices are the block's loop on the free surface (a block with no
  // finite corners, or not one polyhedron), not its corners.
  bool vertices_are_surface_loop = false;
  std::string report_text;           // the block's report JSON, indented
  std::vector<std::string> summary;  // ui/blocks/block_summary.h: the report in words
  BlockVerdict verdict = BlockVerdict::infinite;
  // The motion after failure (analysis.dynamics), points datum-relative.
  std::optional<analysis::ReportDynamics> dynamics;
};

// datum: the project's, subtracted from the report's absolute coordinates.
BlockView make_block_view(const storage::BlockResult& block, const Eigen::Vector3d& datum);

}  // namespace rockface::ui
