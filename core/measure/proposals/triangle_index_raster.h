#pragma once
// Triangles drawn into an index image (CV_32S): a pixel takes a
// triangle's index when its square (its centre +- half a pixel) reaches the
// triangle, its closed inside, as cv::fillConvexPoly's fill with its edges
// reached them. A mesh drawn in order leaves each pixel the last triangle
// that reaches it; a mesh that tiles a region leaves no pixel of it
// uncovered, and a gap narrower than a pixel (a triangle dropped across a
// depth jump) is closed as the drawn edges closed it.
//
// Why not cv::fillConvexPoly: at 24 Mpx the surface image is drawn from
// 2.7 million triangles of one or two pixels each, and the fill's own
// per-call work (scalar to pixel value, edge set-up, clipping) was most
// of the drawing (issue 45). The test is exact in integers and made pixel
// by pixel, so a stripe of rows drawn on its own gives the whole image's
// pixels: the stripes need no overlap.
#include <opencv2/core.hpp>

namespace rockface::measure::proposals {

// Sub-pixel precision of the corners: 1/16 px.
constexpr int kRasterShift = 4;

// Draws `index` into the pixels of `rows` (CV_32S, the rows of a larger
// image starting at row `first_row` of it) whose squares reach the
// triangle of `corners` (image pixels << kRasterShift; a pixel's centre
// is at its integer coordinates). A triangle without area draws nothing.
void draw_triangle_index(cv::Mat& rows, int first_row, const cv::Point corners[3], int index);

}  // namespace rockface::measure::proposals
