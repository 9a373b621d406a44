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
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "camera/camera.h"
#include "core/common/preset.h"
#include "core/common/progress.h"
#include "core/rockmass/classification_form.h"
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

// The rock mass of a visit (issue 23): its figures and classifications in
// words, with the form entered for it (saved first when given).
class RockMassRunner {
 public:
  virtual ~RockMassRunner() = default;
  // Throws InputError naming the field for a form value out of range, or
  // the visit when it has no traces.
  virtual std::vector<std::string> figures(const std::filesystem::path& project,
                                           storage::RecordId visit_id,
                                           const std::optional<rockmass::ClassificationForm>& save,
                                           Progress& progress) = 0;
};

struct FieldServices {
  ReconstructionRunner* reconstruction = nullptr;  // null: the Model screen cannot reconstruct
  AnalysisRunner* analysis = nullptr;              // null: the Blocks screen cannot analyse
  CameraConnector* camera = nullptr;               // null: no camera
  TunnelRunner* tunnel = nullptr;                  // null: the Project screen shows no tunnel views
  RockMassRunner* rockmass = nullptr;              // null: the Blocks screen shows no rock mass
};

}  // namespace rockface::ui
