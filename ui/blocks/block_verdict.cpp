#include "ui/blocks/block_verdict.h"

namespace rockface::ui {

const char* verdict_name(BlockVerdict verdict) {
  switch (verdict) {
    case BlockVerdict::moves:
      return "moves";
    case BlockVerdict::marginal:
      return "marginal";
    case BlockVerdict::holds:
      return "holds";
    case BlockVerdict::keyed:
      return "keyed";
    case BlockVerdict::infinite:
      return "not finite";
  }
  return "?";
}

BlockVerdict verdict_of(const storage::BlockResult& b) {
  if (b.marginal) return BlockVerdict::marginal;
  if (!b.finite) return BlockVerdict::infinite;
  if (!b.removable) return BlockVerdict::keyed;
  if (b.mode == "none") return BlockVerdict::holds;
  if (b.mode == "falling" || b.mode == "lifting" || !b.fos || *b.fos < 1)
    return BlockVerdict::moves;
  return BlockVerdict::holds;
}

}  // namespace rockface::ui
