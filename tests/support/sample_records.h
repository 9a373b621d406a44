#pragma once
// Sample records for the storage tests: small real JPEG/PNG images encoded by
// OpenCV (textured, so they are realistic JPEG streams), and one record of
// every kind with every field set to something other than its default.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "storage/project/project_records.h"
#include "storage/project/project_sqlite.h"

namespace rockface::storage::test {

// A textured 8-bit image encoded as ".jpg" or ".png"; seed varies the content.
std::vector<std::uint8_t> encoded_image(int width, int height, int seed, const std::string& ext);

ProjectInfo sample_project();
Calibration sample_calibration();
Capture sample_capture(RecordId visit_id, int seed, int width = 640, int height = 480);
Model sample_model(std::optional<RecordId> capture_id);
std::vector<Measurement> sample_measurements(std::optional<RecordId> model_id);
std::vector<JointSet> sample_joint_sets();
std::vector<Joint> sample_joints();
AnalysisRun sample_analysis(RecordId visit_id, std::optional<RecordId> model_id);

// A fresh empty folder under the system temp dir, removed when destroyed.
class TempDir {
 public:
  explicit TempDir(const std::string& name);
  ~TempDir();
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& leaf) const { return path_ / leaf; }

 private:
  std::filesystem::path path_;
};

std::vector<std::uint8_t> read_file_bytes(const std::filesystem::path& file);

// A project file as rockface wrote it at an older schema `version`: schema 1
// upgraded step by step, then the project's row and one visit (id 1).
// The connection is left open for the test's own rows of that schema.
sqlite::Connection project_at_schema(const std::filesystem::path& file, int version);

}  // namespace rockface::storage::test
