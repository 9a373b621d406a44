#pragma once
// A picture written as PNG through the one atomic writer (a reader never
// sees half a file). Throws Error naming the file.
#include <filesystem>

#include <opencv2/core.hpp>

namespace rockface::app {

void write_png(const std::filesystem::path& file, const cv::Mat& image);

}  // namespace rockface::app
