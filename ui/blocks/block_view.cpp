#include "ui/blocks/block_view.h"

#include <utility>

#include "ui/blocks/block_summary.h"

namespace rockface::ui {

BlockView make_block_view(analysis::ReportBlock block) {
  BlockView v;
  v.verdict = analysis::verdict_of(block);
  v.summary = block_summary(block);
  v.block = std::move(block);
  return v;
}

}  // namespace rockface::ui
