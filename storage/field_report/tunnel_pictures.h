#pragma once
// The tunnel's pictures, drawn with OpenCV for `rockface profile`,
// `rockface drive`, the field report and the tablet:
// - the developed view of a round: the excavated surface's deviation from
//   the design line unrolled (arc length of the outline across, chainage up
//   toward the face), overbreak red, underbreak blue, white on the line, not
//   seen hatched grey, the range pole (not rock) dark grey, underbreak
//   beyond tolerance outlined in black, a colour scale bar in cm;
// - the sets along the drive: each set's dip and dip direction against
//   chainage, one colour per set, a set that appears, vanishes or turns
//   marked where it does.
#include <opencv2/core.hpp>

#include "core/tunnel/design_profile.h"
#include "core/tunnel/drive_sets.h"
#include "core/tunnel/profile_deviation.h"

namespace rockface::storage {

// BGR, about width_px wide (the height follows the round's length at the
// same metres per pixel, bounded). Empty view: a picture that says so.
cv::Mat developed_view_picture(const tunnel::ProfileDeviation& deviation,
                               const tunnel::DesignProfile& profile, int width_px = 900);

// The developed view's colour scale: the seen deviations' 98th percentile,
// at least 10 cm and twice the tolerance, rounded up to 5 cm (m).
double developed_view_scale_m(const tunnel::ProfileDeviation& deviation);

// The developed view's cells alone into `img`, w x h pixels from `at`
// (the face at the top), framed, with the underbreak beyond tolerance
// outlined and the deepest underbreak marked: what the picture above draws
// and the tablet shows with its own labels (issue 39). The frame takes one
// pixel past w and h; the outline up to one more on each side.
void draw_developed_view_cells(cv::Mat& img, cv::Point at, int w, int h,
                               const tunnel::ProfileDeviation& deviation,
                               const tunnel::DesignProfile& profile, double scale_m);

// BGR, width_px x height_px: two panels (dip direction above, dip below)
// against chainage.
cv::Mat drive_picture(const tunnel::DriveSets& drive, int width_px = 1000, int height_px = 700);

// The colour of track `id` (1, 2, ...) in the drive picture, BGR.
cv::Scalar drive_set_colour(int id);

}  // namespace rockface::storage
