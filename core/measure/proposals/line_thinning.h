#pragma once
// Zhang-Suen thinning of the cues' line images (line_evidence.h), visiting
// only the set pixels: the lines are a few pixels wide on an image of
// millions, and a scan of the whole image per sub-iteration (as
// cv::ximgproc::thinning does) was most of the thinning's time.
#include <opencv2/core.hpp>

namespace rockface::measure::proposals {

// `binary`: CV_8U, 0 or 255. Returns CV_8U 0 / 255: the same pixels as
// cv::ximgproc::thinning(binary, out, THINNING_ZHANGSUEN) gives (the two
// sub-iterations each deciding on the image as it stood before it, the
// outermost rows and columns never removed, repeated until nothing moves).
cv::Mat zhang_suen_thinning(const cv::Mat& binary);

}  // namespace rockface::measure::proposals
