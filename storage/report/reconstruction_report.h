#pragma once
// The reconstruction report (`rockface reconstruct --report`), format
// rockface-reconstruction/1: what was reconstructed, how it was oriented and
// registered, and how accurate it is predicted and measured to be.
#include <string>

#include "core/photogrammetry/reconstruction/multi_image_registration.h"
#include "core/photogrammetry/reconstruction/reconstruction.h"

namespace rockface::storage {

struct ReconstructionReportContext {
  std::string left_image, right_image, preset;
  std::optional<double> range_pole_m, baseline_m;
  std::optional<photogrammetry::NorthReference> north;
};

std::string reconstruction_report_json(const photogrammetry::ReconstructionResult& result,
                                       const ReconstructionReportContext& context);

// Several 3D images of one face (format rockface-face-registration/1): per
// image how it was registered and its residuals (tie points, surface
// overlap), and per ground control point its residual.
std::string face_registration_json(const photogrammetry::FaceRegistration& face);

}  // namespace rockface::storage
