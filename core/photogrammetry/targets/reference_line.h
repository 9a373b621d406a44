#pragma once
// The reference line whose compass bearing gives north: two pixels of the
// left image, written "U1,V1,U2,V2" on the command line.
#include <array>
#include <string>

#include <Eigen/Core>

namespace rockface::photogrammetry {

// Parses "U1,V1,U2,V2" (finite numbers, the points at least 10 px apart).
// Throws InputError naming `where` and the reason.
std::array<Eigen::Vector2d, 2> parse_reference_line(const std::string& text,
                                                    const std::string& where);

}  // namespace rockface::photogrammetry
