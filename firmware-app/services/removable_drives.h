#pragma once
// The USB sticks the tablet sees, for its exports and its imports (issue
// 43): the drives mounted under /media or /run/media (udisks2's automount of
// removable drives), or the folder ROCKFACE_USB_DIR names (a tablet whose
// stick has a fixed mount point; the tests).
#include <filesystem>
#include <string>
#include <vector>

namespace rockface::app {

struct RemovableDrive {
  std::filesystem::path folder;
  std::string label;  // "USB stick KINGSTON"
};

// Those mounted now that the tablet may write to (`writable`), else read.
std::vector<RemovableDrive> removable_drives(bool writable);

}  // namespace rockface::app
