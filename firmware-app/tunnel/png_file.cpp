#include "firmware-app/tunnel/png_file.h"

#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "core/common/error.h"
#include "storage/export_file.h"

namespace rockface::app {

void write_png(const std::filesystem::path& file, const cv::Mat& image) {
  std::vector<unsigned char> bytes;
  if (image.empty() || !cv::imencode(".png", image, bytes))
    throw Error(file.string() + ": cannot encode the picture as PNG");
  storage::write_file_atomically(file, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
  });
}

}  // namespace rockface::app
