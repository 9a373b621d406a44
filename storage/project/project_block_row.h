#pragma once
// One analysed block as the project file's `block` table holds it: the key
// columns for lists and queries (label, source, code, volume, verdict, mode,
// factor of safety) and the block's report JSON verbatim (SCENE.md "blocks"
// entry). Everything above storage reads the verdict as
// analysis::ReportBlock; this maps it to the row and back. Internal to
// storage.
#include <optional>
#include <string>

#include "core/analysis/report.h"

namespace rockface::storage {

struct BlockRow {
  std::string label;   // "B1"
  std::string source;  // "scene" | "traces"
  std::string code;    // half-space code, one digit per plane
  double volume_m3 = 0;
  bool finite = false, removable = false, marginal = false;
  std::string mode;  // "falling" | "lifting" | "sliding" | "none"
  std::optional<double> fos;
  std::string report_json;
};

// The row a verdict is stored as (the same bytes as ever: report.h's
// block_to_json and the columns from the same values).
BlockRow block_row(const analysis::ReportBlock& block);

// The verdict a stored row holds: its report JSON read back
// (block_from_json), the key columns winning where both say it (a row
// stored by an older version may have a short report JSON). The volume and
// factor of safety are the columns' (full precision; the JSON rounds them).
analysis::ReportBlock block_of_row(const BlockRow& row);

}  // namespace rockface::storage
