#include "firmware-app/propose/huge_page_images.h"

#include <sys/mman.h>

#include <cstdint>

namespace rockface::app {

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

std::size_t rounded_up(std::size_t bytes) {
  return (bytes + kHugePage - 1) / kHugePage * kHugePage;
}

// Marks a block this allocator mapped (UMatData::userdata), as against
// one from OpenCV's allocator or the caller's own.
int mapped_tag;

// `bytes` rounded up to whole huge pages at a huge page's boundary, asked
// for in huge pages; null when the system has no such mapping to give.
void* map_huge(std::size_t bytes) {
  const std::size_t length = rounded_up(bytes);
  void* raw =
      mmap(nullptr, length + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) return nullptr;
  const auto start = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (start + kHugePage - 1) / kHugePage * kHugePage;
  // Only the aligned part is kept: the head and tail are handed back now.
  if (aligned > start) munmap(raw, aligned - start);
  const std::uintptr_t tail = aligned + length, end = start + length + kHugePage;
  if (end > tail) munmap(reinterpret_cast<void*>(tail), end - tail);
  // A kernel without transparent huge pages refuses the advice: the block
  // is still good memory in ordinary pages.
  madvise(reinterpret_cast<void*>(aligned), length, MADV_HUGEPAGE);
  return reinterpret_cast<void*>(aligned);
}

// OpenCV's own allocator (cv::StdMatAllocator) for every block but the
// large ones it makes itself.
class HugePageImageAllocator final : public cv::MatAllocator {
 public:
  cv::UMatData* allocate(int dims, const int* sizes, int type, void* data0, std::size_t* step,
                         cv::AccessFlag flags, cv::UMatUsageFlags usage) const override {
    std::size_t total = CV_ELEM_SIZE(type);
    for (int i = dims - 1; i >= 0; --i) {
      if (step) {
        if (data0 && step[i] != cv::Mat::AUTO_STEP) {
          CV_Assert(total <= step[i]);
          total = step[i];
        } else {
          step[i] = total;
        }
      }
      total *= static_cast<std::size_t>(sizes[i]);
    }
    if (data0 || total < kHugePageImageBytes)
      return cv::Mat::getStdAllocator()->allocate(dims, sizes, type, data0, step, flags, usage);
    void* data = map_huge(total);
    if (!data)
      return cv::Mat::getStdAllocator()->allocate(dims, sizes, type, data0, step, flags, usage);
    auto* u = new cv::UMatData(this);
    u->data = u->origdata = static_cast<uchar*>(data);
    u->size = total;
    u->userdata = &mapped_tag;
    return u;
  }

  bool allocate(cv::UMatData* u, cv::AccessFlag, cv::UMatUsageFlags) const override {
    return u != nullptr;
  }

  void deallocate(cv::UMatData* u) const override {
    if (!u) return;
    CV_Assert(u->urefcount == 0 && u->refcount == 0 && u->userdata == &mapped_tag);
    munmap(u->origdata, rounded_up(u->size));
    delete u;
  }
};

}  // namespace

cv::MatAllocator* huge_page_image_allocator() {
  static auto* allocator = new HugePageImageAllocator;
  return allocator;
}

HugePageImages::HugePageImages() : before_(cv::Mat::getDefaultAllocator()) {
  cv::Mat::setDefaultAllocator(huge_page_image_allocator());
}

HugePageImages::~HugePageImages() {
  cv::Mat::setDefaultAllocator(before_);
}

}  // namespace rockface::app
