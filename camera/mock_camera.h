#pragma once
// The mock camera: stands in for the DSLR on a desktop and in tests.
//
// - Replay: a folder of earlier captures (a site visit) served in file-name
//   order, which is the order a camera numbers its shots. Each JPEG comes
//   with its EXIF and, as companions, the other files of the same stem (the
//   RAW of a RAW+JPEG shot). Settings may be set (the workflow sets them
//   before shooting) but the served shots keep the EXIF they were taken with.
// - Synthetic: renders a scene's imaging section; shot 1 is the left
//   station, shot 2 the right. The JPEG carries EXIF made from the settings
//   (focal length from fx and the sensor width, f-number, ISO, shutter,
//   flash, focus distance); with a RAW+JPEG image format the lossless PNG
//   render comes as the companion.
//
// Capture, live view and events behave as the DSLR's do, so the workflow
// above the Camera interface is tested through this class.
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "camera/camera.h"
#include "camera/synthetic_scene.h"

namespace rockface::camera {

// What the synthetic camera writes into EXIF about itself.
struct SyntheticCameraBody {
  std::string make = "rockface";
  std::string model = "synthetic camera";
  std::string lens = "synthetic lens";
  double sensor_width_mm = 23.5;  // APS-C: focal length in mm = fx * width_mm / width_px
};

class MockCamera final : public Camera {
 public:
  // Throws InputError naming the folder when it holds no JPEG.
  static std::unique_ptr<MockCamera> replay(const std::string& folder,
                                            const std::string& spool_dir = {});
  static std::unique_ptr<MockCamera> synthetic(SyntheticScene scene,
                                               const std::string& spool_dir = {},
                                               SyntheticCameraBody body = {});

  std::string model() override;
  std::vector<CameraSetting> settings() override;
  CameraSetting setting(const std::string& name) override;
  void set_setting(const std::string& name, const std::string& value) override;
  void apply(const ExposureSettings& exposure) override;
  FlashState flash() override;
  void lock_focus() override;
  Capture capture() override;
  cv::Mat live_view() override;
  std::vector<CameraEvent> events(int timeout_ms) override;
  void close() override;

  // Shots still to be served.
  size_t shots_left() const;

 private:
  MockCamera() = default;
  CameraSetting& find(const std::string& name);
  CapturedFile store(const std::string& name, std::vector<uint8_t> data);
  Capture capture_replay();
  Capture capture_synthetic();

  struct ReplayShot {
    std::string image;
    std::vector<std::string> companions;
  };
  enum class Mode { replay, synthetic } mode_ = Mode::replay;
  std::string folder_, spool_dir_;
  std::vector<ReplayShot> shots_;
  std::optional<SyntheticScene> scene_;
  SyntheticCameraBody body_;
  size_t next_ = 0;
  std::vector<CameraSetting> settings_;
  std::optional<double> locked_focus_m_;
  bool focus_locked_ = false;
  std::deque<CameraEvent> events_;
  bool closed_ = false;
};

}  // namespace rockface::camera
