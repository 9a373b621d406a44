#pragma once
// A scanner's return intensity as the cloud's colours (issue 43): a
// terrestrial scan without a camera ("x y z intensity" text, PTX without
// RGB, LAS point formats 0, 1 and 6) has no colours, yet its targets and its
// rock's texture show in its intensity. Where the file holds no colours,
// each point's intensity becomes a grey, scaled linearly from the file's own
// range (its least intensity black, its greatest white): what the 3D view
// draws, the virtual view the geologist maps on shows and `import --pole
// auto` finds the range pole's targets in. The file's intensity units
// (0..1, 0..255, 0..65535, a scanner's signed dB) need not be known.
#include "storage/exchange/imported_surface.h"

namespace rockface::storage {

// When `s` has intensities and no colours: its colours from them, the
// range recorded in s.intensity_as_grey. The intensities are emptied either
// way (their memory: 4 bytes a point). A file whose intensity is the same
// everywhere comes out mid grey. Throws InputError naming `source` for an
// intensity that is not finite or an intensity count not the points'.
void grey_from_intensity(ImportedSurface& s, const std::string& source);

}  // namespace rockface::storage
