#include <gtest/gtest.h>
#include <cstdlib>
#include <opencv2/imgcodecs.hpp>

#include "core/photogrammetry/matching/image_contrast.h"
#include "tests/integration_lighting/lit_face.h"

using namespace rockface;
using namespace rockface::testing;

TEST(Sweep, Print) {
  if (!std::getenv("SWEEP")) GTEST_SKIP();
  auto run = [](const char* name, camera::SyntheticEffects e) {
    const auto o = reconstruct_lit_face(lit_face(e));
    const auto c = photogrammetry::measure_contrast(o.render.images[0]);
    std::printf("SWEEP %-28s texture %.2f noise %.2f\n", name, c.texture_grey, c.noise_grey);
    if (std::getenv("DUMP"))
      cv::imwrite(std::string("/tmp/lt/") + name + ".png", o.render.images[0]);
    if (o.truth)
      std::printf("SWEEP %-28s scale %.3f %% north %.3f facet %.3f target %.3f px pts %zu\n", name,
                  100 * o.truth->scale_error, o.truth->north_error_deg, o.truth->worst_facet_deg,
                  o.truth->worst_target_px, o.truth->facet_points_min);
    else
      std::printf("SWEEP %-28s REFUSED %s\n", name, o.refusal.c_str());
  };
  const std::string which = std::getenv("SWEEP");
  camera::SyntheticEffects e;
  if (which == "base") run("none", e);
  if (which == "flash")
    for (double i : {0.25, 0.5, 1.0, 2.0}) {
      e.flash = camera::SyntheticFlash{i};
      run(("flash " + std::to_string(i)).c_str(), e);
    }
  if (which == "dust")
    for (double v : {60.0, 40.0, 30.0, 25.0, 20.0, 10.0}) {
      e.sensor = camera::SyntheticSensor{800};
      e.dust = camera::SyntheticDust{3.912 / v, 0.35};
      run(("dust V " + std::to_string(v)).c_str(), e);
    }
  if (which == "iso")
    for (double iso : {800.0, 3200.0, 12800.0, 51200.0}) {
      e.sensor = camera::SyntheticSensor{iso};
      run(("iso " + std::to_string(iso)).c_str(), e);
    }
  if (which == "lamp") {
    e.lamps.push_back({Eigen::Vector3d(0, 0.05, 0.55), 100.0});
    run("lamp mid 100", e);
    e.lamps[0].intensity = 60;
    run("lamp mid 60", e);
  }
  if (which == "vig")
    for (double v : {1.0, 2.0}) {
      e.vignetting = v;
      run(("vignetting " + std::to_string(v)).c_str(), e);
    }
  if (which == "jpeg")
    for (int q : {90, 80, 50, 20}) {
      e.jpeg_quality = q;
      run(("jpeg " + std::to_string(q)).c_str(), e);
    }
  if (which == "combo") {
    e.flash = camera::SyntheticFlash{1.0};
    e.sensor = camera::SyntheticSensor{3200};
    e.jpeg_quality = 80;
    run("flash+3200+jpeg80", e);
  }
}
