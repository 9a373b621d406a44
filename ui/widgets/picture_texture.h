#pragma once
// A picture made on a worker (a BGR cv::Mat) shown on a screen: uploaded
// once as a GL texture, drawn scaled to the panel's width.
#include <opencv2/core.hpp>

namespace rockface::ui {

class PictureTexture {
 public:
  PictureTexture() = default;
  PictureTexture(const PictureTexture&) = delete;
  PictureTexture& operator=(const PictureTexture&) = delete;
  ~PictureTexture();

  // On the UI thread (GL): replaces the picture.
  void set(const cv::Mat& bgr);
  void clear();
  bool empty() const { return width_ == 0; }
  // Draws at the cursor, at most max_width pixels wide, keeping the aspect.
  void draw(float max_width) const;

 private:
  unsigned texture_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace rockface::ui
