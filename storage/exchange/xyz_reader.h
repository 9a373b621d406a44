#pragma once
// Reading a point cloud as text, one point a line: XYZ, TXT, CSV, ASC and PTS
// as scanners, CloudCompare and spreadsheets write them. Written here (there
// is no format to take a library for). Values are separated by commas,
// semicolons, spaces or tabs; lines starting with '#' or "//" are comments.
//
// The columns come from, in this order: the names given (--columns), a
// header line of names (x, y, z or easting, northing, elevation; r, g, b or
// red, green, blue; nx, ny, nz; i or intensity; anything else is skipped), or
// the column count when it says them without doubt (3: x y z; 4: x y z
// intensity; 6: x y z r g b; PTS's 7: x y z intensity r g b). A file with an
// intensity and no colours keeps the intensity (ImportedSurface::intensities:
// a scanner's, drawn as grey by intensity_grey.h). Otherwise the file is refused
// asking for --columns. A PTS file begins with its point count, which must be
// the lines that follow.
//
// Colours are 0..255, or 0..1 when every colour value is at most 1 and one is
// fractional. Every line must have the header's column count and finite
// coordinates.
#include <string>
#include <string_view>
#include <vector>

#include "storage/exchange/imported_surface.h"

namespace rockface::storage {

// What one column holds: "x", "y", "z", "r", "g", "b", "nx", "ny", "nz", "i"
// (intensity) or "" (skipped).
using PointColumns = std::vector<std::string>;

// "x,y,z,r,g,b" or "x,y,z,-,r,g,b" ("-" or "skip" skips a column); the
// names a header line may use are accepted too. InputError("--columns", ...)
// when x, y and z are not each named once.
PointColumns parse_point_columns(const std::string& text, const std::string& where);

// `bytes` is the whole file; `source` names it in errors; `columns` empty to
// find them from the file; `pts`: the file begins with its point count.
ImportedSurface parse_xyz(std::string_view bytes, const std::string& source,
                          const PointColumns& columns, bool pts);

}  // namespace rockface::storage
