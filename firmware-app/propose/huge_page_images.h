#pragma once
// cv::Mat's memory for large images in transparent huge pages (issue 45).
//
// A 24 Mpx photograph in floats is 96 MB: 24,000 pages of 4 kB, each
// faulted in on first write. On the 2-core benchmark machine a fault costs
// about 16 us, so converting that photograph took 0.4 s of CPU of which
// 0.005 s was the conversion (docs/accuracy-cost.md). Asked for huge pages
// (madvise MADV_HUGEPAGE, which Debian's kernels honour in their default
// "madvise" mode), the same image faults in 48 times. Blocks of at least
// kHugePageImageBytes are mapped on their own, 2 MB aligned, and handed back
// when the image is freed; smaller ones come from OpenCV's own allocator.
#include <cstddef>

#include <opencv2/core.hpp>

namespace rockface::app {

constexpr std::size_t kHugePageImageBytes = std::size_t{8} << 20;

// The allocator: one for the process, never destroyed (every image made
// with it frees itself through it, whenever that is).
cv::MatAllocator* huge_page_image_allocator();

// While it lives, new images are made with huge_page_image_allocator();
// the allocator that was the default before is the default again after.
class HugePageImages {
 public:
  HugePageImages();
  ~HugePageImages();
  HugePageImages(const HugePageImages&) = delete;
  HugePageImages& operator=(const HugePageImages&) = delete;

 private:
  cv::MatAllocator* before_;
};

}  // namespace rockface::app
