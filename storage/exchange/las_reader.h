#pragma once
// Reading an ASPRS LAS file (versions 1.0 to 1.4; point data record formats
// 0 to 3 and 6 to 8, the ones laser scanners and drone software write): the
// points' X, Y, Z as the header's scale and offset make them (doubles, so
// survey coordinates keep the file's resolution), their RGB where the format
// has it, else their intensity (drawn as grey: intensity_grey.h). Written here: Debian has no LAS
// library. A LAZ file (compressed LAS) is refused naming the tools that decompress it.
//
// Checked before anything is allocated: the signature, the version, the
// header's size and the offset to the points, the record format and length,
// the point count against the bytes the file holds (a 2 GB claim in a small
// file is refused), the legacy and 64-bit counts of LAS 1.4 agreeing, finite
// non-zero scales; then every point against the header's bounding box (a
// header that lies about its points is refused).
#include <filesystem>
#include <string>
#include <string_view>

#include "storage/exchange/imported_surface.h"

namespace rockface::storage {

// `bytes` is the whole file; `source` names it in errors.
ImportedSurface parse_las(std::string_view bytes, const std::string& source);

// The same read from the file in chunks of 8 MiB of records: a 10-million-
// point file (360 MB) is never held whole (issue 43's peak), with the same
// checks and the same words.
ImportedSurface read_las_file(const std::filesystem::path& file);

}  // namespace rockface::storage
