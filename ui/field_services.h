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

// The office server (issue 24): the tablet's one server (a libpq service
// set once per tablet), what waits to go up, and the sync itself.
struct SyncOverview {
  std::string server;  // e.g. "service=rockface"; never a password
  bool ever_synced = false;
  std::string tunnel, last_sync_at, last_outcome;
  int records_waiting = 0, visits_waiting = 0;
};

class SyncRunner {
 public:
  virtual ~SyncRunner() = default;
  // Read from the project alone (no network).
  virtual SyncOverview overview(const std::filesystem::path& project) = 0;
  // Sends what waits; returns what was sent in words. Throws rockface::Error
  // saying so when the server cannot be reached (nothing lost: the next
  // sync resumes), Cancelled when cancelled (likewise).
  virtual std::vector<std::string> sync(const std::filesystem::path& project,
                                        Progress& progress) = 0;
};

struct FieldServices {
  ReconstructionRunner* reconstruction = nullptr;  // null: the Model screen cannot reconstruct
  AnalysisRunner* analysis = nullptr;              // null: the Blocks screen cannot analyse
  CameraConnector* camera = nullptr;               // null: no camera
  TunnelRunner* tunnel = nullptr;                  // null: the Project screen shows no tunnel views
  SyncRunner* sync = nullptr;                      // null: no office server on this tablet
};

}  // namespace rockface::ui
