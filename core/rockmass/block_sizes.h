#pragma once
// The in-situ block size distribution from the face's finite blocks (the
// blocks the traces cut out, core/faces), beside what the sets' spacings
// give (Palmström 2005, "Measurements of and correlations between block
// size and rock quality designation", TUST 20):
//   - the finite blocks' volumes: a histogram by half decades, the median
//     (V50, the typical block), mean, smallest and largest;
//   - Vb from three sets' spacings, the parallelepiped they cut:
//     Vb = S1 S2 S3 / |det(n1, n2, n3)| (= S1 S2 S3 / (sin g1 sin g2 sin g3)
//     for Palmström's angles g between the sets);
//   - Vb from Jv, Vb = beta Jv^-3;
//   - the block shape: Palmström's alpha2 = a2/a1, alpha3 = a3/a1 (a1 <=
//     a2 <= a3 the block's dimensions) and beta = (alpha2 + alpha2 alpha3 +
//     alpha3)^3 / (alpha2 alpha3)^2 (27 for a cube), from the spacings and,
//     per block, from the box with the block's principal moments.
#include <optional>
#include <string>
#include <vector>

#include "core/rockmass/spacing.h"

namespace rockface::rockmass {

struct FaceBlock {
  std::string label;
  double volume_m3 = 0;
  // Principal moments of inertia (kg m2) and mass (kg), for the shape.
  std::optional<Eigen::Vector3d> principal_moments;
  std::optional<double> mass_kg;
};

struct BlockShape {
  double alpha2 = 1, alpha3 = 1, beta = 27;
  std::string words;  // "equidimensional", "moderately long", "flat", ...
};
BlockShape block_shape(double a1, double a2, double a3);  // any order
const char* block_size_words(double volume_m3);           // Palmström's classes

struct BlockSizes {
  int finite_blocks = 0;
  std::vector<double> volumes_m3;
  Histogram histogram;  // edges in m3, half decades
  std::optional<double> v50_m3, mean_m3, min_m3, max_m3;
  std::optional<BlockShape> shape_of_blocks;  // from the blocks' median beta
  // From the sets.
  std::optional<double> vb_from_spacing_m3, vb_from_jv_m3;
  std::optional<BlockShape> shape_from_spacing;
  std::vector<std::string> spacing_sets;  // the three sets used
  std::string size_words;                 // of the Vb shown first
  std::string note;
};

// `set_normals` in the order of `spacings`.
BlockSizes block_sizes(const std::vector<FaceBlock>& blocks,
                       const std::vector<SetSpacing>& spacings,
                       const std::vector<Eigen::Vector3d>& set_normals, std::optional<double> jv);

}  // namespace rockface::rockmass
