#include "core/measure/no_surface_cause.h"

#include <algorithm>
#include <cmath>

#include "core/common/number_format.h"
#include "core/photogrammetry/matching/image_contrast.h"

namespace rockface::measure {

std::string no_surface_cause(const cv::Mat& photo, const std::string& photo_name,
                             const Eigen::Vector2d& pixel) {
  const std::string hole =
      "the two photographs were not matched there (the other photograph may not see that spot, "
      "or something stands in front of it): pick where the 3D image has surface";
  if (photo.empty()) return hole;
  // What dense matching had around the pick: the photograph's own
  // contrast check (image_contrast.h) over a window of 3 % of its width
  // (at least 41 px): wide enough for the check's 15 px texture windows,
  // narrow enough to read one part of the face.
  const int r = std::max(20, photo.cols * 3 / 200);
  const int x = static_cast<int>(std::lround(pixel.x()));
  const int y = static_cast<int>(std::lround(pixel.y()));
  const cv::Rect window =
      cv::Rect(x - r, y - r, 2 * r + 1, 2 * r + 1) & cv::Rect(0, 0, photo.cols, photo.rows);
  if (window.width < 15 || window.height < 15) return hole;
  namespace pg = photogrammetry;
  const pg::ImageContrast c = pg::measure_contrast(photo(window));
  const std::string texture = "texture " + format_fixed(c.texture_grey, 1) + " grey levels";
  const bool no_texture = c.texture_grey < pg::kMinMatchableTexture ||
                          c.texture_grey < pg::kMinTextureToNoise * c.noise_grey;
  const std::string part = "that part of the " + photo_name + " photograph ";
  // The limits are the whole photograph's (image_contrast.h): dark is
  // nine pixels in ten below a quarter of full scale.
  if (no_texture && c.bright_grey < pg::kDarkImage)
    return part + "is too dark to match (nine pixels in ten below " +
           format_fixed(c.bright_grey, 0) + " of 255, " + texture + " around the pick, at least " +
           format_fixed(pg::kMinMatchableTexture, 1) +
           " needed): light that part of the face (flash, lamp) and photograph it again, or pick "
           "where the 3D image has surface";
  if (c.median_grey >= pg::kClippedImage)
    return part + "is burnt out (median " + format_fixed(c.median_grey, 0) +
           " of 255 around the pick): a wet or shiny patch reflects the light; photograph it "
           "from another angle or with less light";
  if (no_texture)
    return part + "has no texture to match (" + texture + " over " + format_fixed(c.noise_grey, 1) +
           " of noise around the pick, at least " + format_fixed(pg::kMinMatchableTexture, 1) +
           " needed): a uniform surface such as shotcrete or a wet film; pick where the 3D image "
           "has surface";
  return hole;
}

}  // namespace rockface::measure
