#pragma once
// A picture written as a file through the one atomic writer
// (core/common/atomic_file.h): encoded in memory in the format the file
// name's extension names (.png, .jpg, .pfm, ...), then written whole, so a
// full card never leaves a truncated picture under the final name.
#include <filesystem>
#include <string>

#include <opencv2/core.hpp>

namespace rockface::storage {

// `format` is an extension such as ".png"; empty means the file name's own.
// Throws rockface::Error naming the file when the picture cannot be encoded
// or written.
void write_image_file(const std::filesystem::path& file, const cv::Mat& image,
                      const std::string& format = {});

}  // namespace rockface::storage
