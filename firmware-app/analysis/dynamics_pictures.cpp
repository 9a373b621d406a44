#include "firmware-app/analysis/dynamics_pictures.h"

#include <cctype>

#include <opencv2/imgcodecs.hpp>

#include "core/common/error.h"
#include "storage/exchange/image_file.h"
#include "storage/field_report/dynamics_picture.h"

namespace rockface::app {

void write_dynamics_pictures(analysis::Report& report, const std::string& report_path) {
  std::string stem = report_path;
  if (stem.size() > 5 && stem.compare(stem.size() - 5, 5, ".json") == 0)
    stem.resize(stem.size() - 5);
  for (analysis::ReportBlock& b : report.blocks) {
    if (!b.dynamics || b.dynamics->path.empty()) continue;
    std::string id = b.id;
    for (char& c : id)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
    const std::string file = stem + "." + id + ".dynamics.png";
    const cv::Mat img = storage::dynamics_picture(b.id, b.vertices, *b.dynamics);
    if (img.empty()) continue;
    storage::write_image_file(file, img);
    const auto slash = file.find_last_of('/');
    b.dynamics->picture = slash == std::string::npos ? file : file.substr(slash + 1);
  }
}

}  // namespace rockface::app
