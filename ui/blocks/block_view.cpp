#include "ui/blocks/block_view.h"

#include "ui/blocks/block_summary.h"

namespace rockface::ui {

BlockView make_block_view(const analysis::ReportBlock& block) {
  BlockView v;
  v.block = block;
  v.verdict = analysis::verdict_of(block);
  v.summary = block_summary(block);
  return v;
}

}  // namespace rockface::ui
