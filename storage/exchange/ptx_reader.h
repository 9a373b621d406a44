#pragma once
// Reading a Leica PTX file (the gridded export of a terrestrial scanner, one
// or more scans one after another). Each scan: its columns and rows, the
// scanner's position and axes, the 4 x 4 matrix that registers it (the last
// row the translation, as PTX writes it), then columns x rows lines "x y z
// intensity [r g b]" in the scanner's frame. A point 0 0 0 is a direction
// with no return: counted, not kept. Without colours each point's intensity
// is kept (ImportedSurface::intensities, drawn as grey by intensity_grey.h).
// Points are registered by the matrix;
// each scanner's registered position is kept (the side the surface was seen
// from: import_surface.h's view side).
// Written here (Debian has no PTX reader).
//
// Every count is checked against the bytes left before anything is
// allocated; every value must be a finite number.
#include <string>
#include <string_view>

#include "storage/exchange/imported_surface.h"

namespace rockface::storage {

ImportedSurface parse_ptx(std::string_view bytes, const std::string& source);

}  // namespace rockface::storage
