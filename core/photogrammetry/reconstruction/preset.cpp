#include "core/photogrammetry/reconstruction/preset.h"

namespace rockface::photogrammetry {

double working_scale(int width, int max_width) {
  if (max_width <= 0 || width <= max_width) return 1.0;
  return static_cast<double>(max_width) / width;
}

ReconstructionPreset preset_fast() {
  ReconstructionPreset p;
  p.name = preset_name(Preset::fast);
  p.feature_max_width = 1600;
  p.max_features = 4000;
  p.refine_iterations = 50;
  p.dense_max_width = 1000;
  p.max_disparities = 128;
  p.sgbm_block_size = 7;
  p.sgbm_three_way = true;
  p.disparity_sigma_px = 0.4;
  p.lattice_step = 2;
  return p;
}

ReconstructionPreset preset_standard() {
  ReconstructionPreset p;
  p.name = preset_name(Preset::standard);
  return p;  // the defaults of the struct are the standard preset
}

ReconstructionPreset preset_precise() {
  ReconstructionPreset p;
  p.name = preset_name(Preset::precise);
  p.feature_max_width = 4000;
  p.max_features = 16000;
  p.ratio_test = 0.75;
  p.refine_iterations = 200;
  p.dense_max_width = 3000;
  p.max_disparities = 512;
  p.sgbm_block_size = 5;
  p.sgbm_three_way = false;  // MODE_SGBM: 5 paths in one pass, slower than 3-way
  p.disparity_sigma_px = 0.25;
  return p;
}

ReconstructionPreset reconstruction_preset(Preset preset) {
  switch (preset) {
    case Preset::fast:
      return preset_fast();
    case Preset::standard:
      return preset_standard();
    case Preset::precise:
      return preset_precise();
  }
  return preset_standard();  // not reached: every enumerator is handled above
}

}  // namespace rockface::photogrammetry
