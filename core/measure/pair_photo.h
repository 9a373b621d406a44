#pragma once
// The names of a visit's photographs, one stereo pair each: the first
// pair's "left" and "right", a further pair's "pair 2 left". Picks
// (picks.h) name a photograph and its pair apart; the measurements
// (pick_measurement.h) and the stored records name the photograph alone.
#include <string>

#include "core/measure/picks.h"

namespace rockface::measure {

// The name of a pair's photograph in MeasureContext (views, pickers,
// photos) and in the stored measurements: "left" / "right" for the first
// pair, "pair 2 left" for a further one.
std::string pair_photo(int pair, const std::string& side);

// The pair of a photograph named by pair_photo (1 for "left", "right" and
// for none).
int pair_of_photo(const std::string& photo);

// The picks with each further pair's photograph named by pair_photo, so
// that they are measured through that pair's view and on its 3D image.
Picks picks_by_pair_photo(Picks picks);

}  // namespace rockface::measure
