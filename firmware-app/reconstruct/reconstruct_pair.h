#pragma once
// Two-view reconstruction from photograph files to model files (`rockface
// reconstruct`): every argument checked before the long work starts, the
// pair reconstructed and registered (range pole, compass line, control
// points, base), the model written as PLY or OBJ and, when asked, its
// accuracy report (rockface-reconstruction/1), each file whole or not at all.
#include <optional>
#include <string>

#include "core/common/progress.h"
#include "core/photogrammetry/reconstruction/reconstruction.h"
#include "firmware-app/reconstruct/registration_options.h"

namespace rockface::app {

struct PairReconstructionRequest {
  std::string left, right;           // the photographs
  std::string camera, right_camera;  // calibrations; right_camera empty: the same camera
  std::string preset = "standard";
  RegistrationOptions registration;  // pole, compass line, control points, base
  std::string out;                   // MODEL.ply or MODEL.obj
  std::string report;                // accuracy report; empty: none
};

// Throws InputError naming the option or file at fault, before any long work.
photogrammetry::ReconstructionResult reconstruct_pair_files(
    const PairReconstructionRequest& request, Progress& progress);

}  // namespace rockface::app
