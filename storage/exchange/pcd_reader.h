#pragma once
// Reading a PCL point cloud file (PCD v0.7 and earlier; DATA ascii or
// binary): the fields x, y, z (float or double), rgb / rgba (packed, as PCL
// writes them) and normal_x, normal_y, normal_z; other fields skipped. A
// binary_compressed file is refused naming the tool that converts it
// (pcl_convert_pcd_ascii_binary). In an organised cloud (HEIGHT > 1) a point
// with NaN coordinates is a pixel with no return: counted, not kept; in an
// unorganised one it is an error.
//
// Written here, not Open3D's reader: Open3D reports a bad file by a log line
// and an empty cloud, where the import must say which file and which place is
// wrong, and its point type is float-free only by a copy.
#include <string>
#include <string_view>

#include "storage/exchange/imported_surface.h"

namespace rockface::storage {

ImportedSurface parse_pcd(std::string_view bytes, const std::string& source);

}  // namespace rockface::storage
