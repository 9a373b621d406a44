// Issue 42: a photograph gets the calibration of the camera that took it —
// the same body (make, model, serial number), lens and focal setting, at the
// same image size — from the project's library; with none, a refusal that
// says what the photograph needs and what to do.
#include <gtest/gtest.h>

#include "storage/project/calibration_library.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

struct Library {
  test::TempDir dir{"calibration-library"};
  ProjectStore store = ProjectStore::create(dir / "site.rockface", test::sample_project());

  RecordId add(const std::string& model, const std::string& serial, const std::string& lens,
               double focal_mm, int width, int height, double fx) {
    Calibration c = test::sample_calibration();
    c.body_id = store.save_camera_body({0, "NIKON CORPORATION", model, serial});
    c.intrinsics.lens = lens;
    c.intrinsics.width = width;
    c.intrinsics.height = height;
    c.intrinsics.fx = c.intrinsics.fy = fx;  // distinct values: distinct calibrations
    c.focal_setting_mm = focal_mm;
    return store.save_calibration(c);
  }
};

PhotoCamera d750(double focal_mm = 24) {
  PhotoCamera p;
  p.make = "NIKON CORPORATION";
  p.model = "NIKON D750";
  p.serial = "3012345";
  p.lens = "24.0-70.0 mm f/2.8";
  p.focal_mm = focal_mm;
  p.width = 6016;
  p.height = 4016;
  return p;
}

TEST(CalibrationLibrary, APhotographGetsItsOwnCamerasCalibration) {
  Library lib;
  const RecordId other_body = lib.add("NIKON D750", "3099999", "24.0-70.0 mm f/2.8", 24, 6016,
                                      4016, 5000);
  const RecordId at_35 = lib.add("NIKON D750", "3012345", "24.0-70.0 mm f/2.8", 35, 6016, 4016,
                                 7300);
  const RecordId small_jpeg = lib.add("NIKON D750", "3012345", "24.0-70.0 mm f/2.8", 24, 3008,
                                      2008, 2500);
  const RecordId right = lib.add("NIKON D750", "3012345", "24.0-70.0 mm f/2.8", 24, 6016, 4016,
                                 5010);
  const RecordId other_lens = lib.add("NIKON D750", "3012345", "50.0 mm f/1.8", 24, 6016, 4016,
                                      5020);
  // The newest stored is another lens's: the one of this lens is chosen.
  CalibrationChoice c = choose_calibration(lib.store, d750());
  ASSERT_TRUE(c.calibration) << c.refusal;
  EXPECT_EQ(c.calibration->id, right);
  c = choose_calibration(lib.store, d750(35));
  ASSERT_TRUE(c.calibration) << c.refusal;
  EXPECT_EQ(c.calibration->id, at_35);
  PhotoCamera small = d750();
  small.width = 3008;
  small.height = 2008;
  c = choose_calibration(lib.store, small);
  ASSERT_TRUE(c.calibration) << c.refusal;
  EXPECT_EQ(c.calibration->id, small_jpeg);
  PhotoCamera second_body = d750();
  second_body.serial = "3099999";
  c = choose_calibration(lib.store, second_body);
  ASSERT_TRUE(c.calibration) << c.refusal;
  EXPECT_EQ(c.calibration->id, other_body);
  (void)other_lens;
}

TEST(CalibrationLibrary, FocalSettingsHalfAMillimetreApartAreOneSetting) {
  Library lib;
  const RecordId at_24 = lib.add("NIKON D750", "3012345", "24.0-70.0 mm f/2.8", 24, 6016, 4016,
                                 5010);
  // EXIF gives the zoom setting to 0.1 mm or better; 24.3 is the lens taped at 24.
  CalibrationChoice c = choose_calibration(lib.store, d750(24.3));
  ASSERT_TRUE(c.calibration);
  EXPECT_EQ(c.calibration->id, at_24);
  c = choose_calibration(lib.store, d750(26));
  EXPECT_FALSE(c.calibration);
}

TEST(CalibrationLibrary, NoneFitsSaysWhatThePhotographNeedsAndWhatToDo) {
  Library lib;
  CalibrationChoice c = choose_calibration(lib.store, d750());
  EXPECT_FALSE(c.calibration);
  EXPECT_NE(c.refusal.find("no calibration of NIKON D750 (serial 3012345), lens 24.0-70.0 mm "
                           "f/2.8 at 24 mm, 6016 x 4016 px"),
            std::string::npos)
      << c.refusal;
  EXPECT_NE(c.refusal.find("calibrate"), std::string::npos) << c.refusal;
  lib.add("NIKON D750", "3012345", "24.0-70.0 mm f/2.8", 24, 3008, 2008, 2500);
  c = choose_calibration(lib.store, d750());
  EXPECT_FALSE(c.calibration);
  EXPECT_NE(c.refusal.find("calibrated at 3008 x 2008 px"), std::string::npos) << c.refusal;
}

// What a photograph does not say is not held against a calibration: a body
// without a serial number in its EXIF, a lens that does not name itself.
TEST(CalibrationLibrary, WhatAPhotographDoesNotSayIsNotHeldAgainstIt) {
  Library lib;
  const RecordId id = lib.add("NIKON D750", "3012345", "24.0-70.0 mm f/2.8", 24, 6016, 4016, 5010);
  PhotoCamera quiet = d750();
  quiet.serial.clear();
  quiet.lens.clear();
  quiet.focal_mm.reset();
  const CalibrationChoice c = choose_calibration(lib.store, quiet);
  ASSERT_TRUE(c.calibration) << c.refusal;
  EXPECT_EQ(c.calibration->id, id);
  PhotoCamera canon = quiet;
  canon.make = "Canon";
  canon.model = "Canon EOS 5D Mark IV";
  EXPECT_FALSE(choose_calibration(lib.store, canon).calibration);
}

}  // namespace
}  // namespace rockface::storage
