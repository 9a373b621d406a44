#pragma once
// What the screens need from above the UI layer. The analysis and the
// reconstruction are composed in firmware-app (the composition root), which
// the UI must not include; the screens call these interfaces on a worker
// thread (BackgroundTask) and firmware-app passes the implementations in.
//
// Every runner opens its own ProjectStore on the project file (one SQLite
// connection per thread), saves what it made as soon as it is made, and
// returns the id of the record.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "camera/camera.h"
#include "core/common/preset.h"
#include "core/common/progress.h"
#include "storage/project_records.h"

namespace rockface::ui {

class ReconstructionRunner {
 public:
  virtual ~ReconstructionRunner() = default;
  // A textured, registered model of a stored capture at `preset`. Returns
  // the model's id.
  virtual storage::RecordId reconstruct(const std::filesystem::path& project,
                                        storage::RecordId capture_id, Preset preset,
                                        Progress& progress) = 0;
};

class AnalysisRunner {
 public:
  virtual ~AnalysisRunner() = default;
  // The block analysis of a visit's joints, traces and surface as stored.
  // Returns the analysis id.
  virtual storage::RecordId analyse(const std::filesystem::path& project,
                                    storage::RecordId visit_id, Progress& progress) = 0;
};

// The camera of the Capture screen: the DSLR when one is attached, else a
// mock camera (a replay folder or a synthetic scene).
class CameraConnector {
 public:
  virtual ~CameraConnector() = default;
  // Throws rockface::Error saying why no camera could be connected.
  virtual std::unique_ptr<camera::Camera> connect() = 0;
  // What connect() will try, e.g. "mock camera: synthetic scene tunnel-face".
  virtual std::string describe() const = 0;
};

// A picture with the lines that go with it (the tunnel's views).
struct TunnelPicture {
  cv::Mat bgr;
  std::vector<std::string> lines;
};

// The tunnel around the visits: the excavation of a visit's round against
// the design profile, and the joint sets along the drive.
class TunnelRunner {
 public:
  virtual ~TunnelRunner() = default;
  // Throw rockface::Error / InputError saying why (no tunnel, visit not placed).
  virtual TunnelPicture profile(const std::filesystem::path& project, storage::RecordId visit_id,
                                Progress& progress) = 0;
  virtual TunnelPicture drive(const std::filesystem::path& project, Progress& progress) = 0;
  // Places the visit by the chainage, offset and height (m above the axis)
  // the geologist typed for the range pole's lower target; returns what was
  // placed in words.
  virtual std::vector<std::string> place(const std::filesystem::path& project,
                                         storage::RecordId visit_id, double chainage, double offset,
                                         double height, Progress& progress) = 0;
};

// The wedges around the excavation (issue 23) for the Blocks screen's
// Wedges view: the wedges of the project's tunnel with a visit's sets, as
// a table already in words and units, with the section picture.
struct WedgeTable {
  std::vector<std::string> lines;    // the input: section, axis, sets, effects
  std::vector<std::string> columns;  // headings with units
  std::vector<std::vector<std::string>> rows;
  std::vector<bool> marginal;      // per row: a verdict inside the uncertainty
  std::vector<std::string> notes;  // corners crossed, pyramids with no wedge, assumptions
  cv::Mat bgr;                     // the section and the largest wedges
};

class WedgeRunner {
 public:
  virtual ~WedgeRunner() = default;
  // Throws rockface::InputError saying why (no tunnel, fewer than three sets).
  virtual WedgeTable wedges(const std::filesystem::path& project, storage::RecordId visit_id,
                            Progress& progress) = 0;
};

struct FieldServices {
  ReconstructionRunner* reconstruction = nullptr;  // null: the Model screen cannot reconstruct
  AnalysisRunner* analysis = nullptr;              // null: the Blocks screen cannot analyse
  CameraConnector* camera = nullptr;               // null: no camera
  TunnelRunner* tunnel = nullptr;                  // null: the Project screen shows no tunnel views
  WedgeRunner* wedges = nullptr;                   // null: the Blocks screen shows no Wedges view
};

}  // namespace rockface::ui
