#include "storage/project/project_block_row.h"

#include "storage/report/report.h"

namespace rockface::storage {

BlockRow block_row(const analysis::ReportBlock& b) {
  BlockRow r;
  r.label = b.id;
  r.source = b.source;
  r.code = b.code;
  r.volume_m3 = b.volume.value_or(0);
  r.finite = b.finite;
  r.removable = b.removable;
  r.marginal = b.marginal;
  r.mode = b.mode ? b.mode->type : "none";
  r.fos = b.fos;
  r.report_json = block_to_json(b);
  return r;
}

analysis::ReportBlock block_of_row(const BlockRow& row) {
  analysis::ReportBlock b = block_from_json(row.report_json);
  b.id = row.label;
  b.source = row.source;
  b.code = row.code;
  // A volume of 0 in the column is "none" unless the report has one.
  if (b.volume || row.volume_m3 != 0) b.volume = row.volume_m3;
  b.finite = row.finite;
  b.removable = row.removable;
  b.marginal = row.marginal;
  // The column says "none" for a block with no mode; a report's own mode
  // object (planes, direction) is kept under the column's type.
  if (b.mode || row.mode != "none") {
    if (!b.mode) b.mode = analysis::ReportMode{};
    b.mode->type = row.mode;
  }
  b.fos = row.fos;
  return b;
}

}  // namespace rockface::storage
