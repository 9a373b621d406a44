// Large images made while HugePageImages lives (firmware-app/propose/
// huge_page_images.h): in their own mapping at a huge page's boundary,
// asked for in huge pages (the kernel's own record of the mapping, /proc's
// smaps), holding what is written to them, handed back when freed; small
// images and the images of earlier or later scopes from OpenCV's allocator.
#include <sys/mman.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "firmware-app/propose/huge_page_images.h"

namespace {

using rockface::app::huge_page_image_allocator;
using rockface::app::HugePageImages;
using rockface::app::kHugePageImageBytes;

// The "VmFlags" line of the mapping holding `p` in /proc/self/smaps, or ""
// when no mapping holds it.
std::string vm_flags_of(const void* p) {
  const auto at = reinterpret_cast<std::uintptr_t>(p);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t from = 0, to = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> from >> dash >> to && dash == '-') {
      inside = at >= from && at < to;
      continue;
    }
    if (inside && line.rfind("VmFlags:", 0) == 0) return line;
  }
  return "";
}

// Whether the kernel takes huge-page advice at all ("never" refuses it).
bool kernel_takes_advice() {
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string text;
  std::getline(mode, text);
  return !text.empty() && text.find("[never]") == std::string::npos;
}

TEST(HugePageImages, ALargeImageIsItsOwnHugePageMappingAndHoldsItsValues) {
  const void* data = nullptr;
  {
    const HugePageImages huge;
    // A 24 Mpx photograph in floats: 96 MB.
    cv::Mat image(4000, 6000, CV_32F);
    ASSERT_EQ(image.u->currAllocator, huge_page_image_allocator());
    data = image.data;
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(data) % (std::size_t{2} << 20), 0u);
    if (kernel_takes_advice()) {
      EXPECT_NE(vm_flags_of(data).find(" hg"), std::string::npos) << vm_flags_of(data);
    }
    cv::randu(image, -1000, 1000);
    const cv::Mat copy = image.clone();  // made in the scope too: a large block of its own
    EXPECT_EQ(cv::norm(image, copy, cv::NORM_INF), 0.0);
    EXPECT_EQ(copy.u->currAllocator, huge_page_image_allocator());
    // Views and shared headers keep the block: freed with the last of them.
    cv::Mat rows = image.rowRange(100, 200);
    image.release();
    EXPECT_EQ(rows.at<float>(0, 0), copy.at<float>(100, 0));
  }
  // Handed back: no mapping holds the block any more.
  EXPECT_EQ(vm_flags_of(data), "");
}

TEST(HugePageImages, SmallImagesAndImagesOutsideTheScopeAreOpenCvsOwn) {
  cv::MatAllocator* before = cv::Mat::getDefaultAllocator();
  {
    const HugePageImages huge;
    const int below = static_cast<int>(kHugePageImageBytes / sizeof(float)) - 1;
    cv::Mat small(1, below, CV_32F, cv::Scalar(3));
    EXPECT_EQ(small.u->currAllocator, cv::Mat::getStdAllocator());
    EXPECT_EQ(small.at<float>(0, below - 1), 3.0f);
    // The caller's own memory stays the caller's.
    static float own[16];
    cv::Mat wrapped(4, 4, CV_32F, own);
    EXPECT_EQ(wrapped.data, reinterpret_cast<uchar*>(own));
  }
  EXPECT_EQ(cv::Mat::getDefaultAllocator(), before);
  cv::Mat large(4000, 6000, CV_32F);
  EXPECT_NE(large.u->currAllocator, huge_page_image_allocator());
}

}  // namespace
