#include "core/analysis/block_verdict.h"

#include <string>

namespace rockface::analysis {

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

BlockVerdict verdict_of(const analysis::ReportBlock& b) {
  if (b.marginal) return BlockVerdict::marginal;
  if (!b.finite) return BlockVerdict::infinite;
  if (!b.removable) return BlockVerdict::keyed;
  const std::string mode = b.mode ? b.mode->type : "none";
  if (mode == "none") return BlockVerdict::holds;
  if (mode == "falling" || mode == "lifting" || !b.fos || *b.fos < 1) return BlockVerdict::moves;
  return BlockVerdict::holds;
}

}  // namespace rockface::analysis
