#include "storage/exchange/image_file.h"

#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "core/common/atomic_file.h"
#include "core/common/error.h"

namespace rockface::storage {

void write_image_file(const std::filesystem::path& file, const cv::Mat& image,
                      const std::string& format) {
  const std::string ext = format.empty() ? file.extension().string() : format;
  std::vector<unsigned char> bytes;
  bool ok = false;
  std::string why;
  try {
    ok = !image.empty() && !ext.empty() && cv::imencode(ext, image, bytes);
  } catch (const cv::Exception& e) {
    why = " (" + e.err + ")";
  }
  if (!ok)
    throw Error(file.string() + ": cannot encode the picture as " +
                (ext.empty() ? std::string("an image (no extension)") : ext) + why);
  write_bytes_atomically(file, bytes.data(), bytes.size());
}

}  // namespace rockface::storage
