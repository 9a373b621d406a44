#include "firmware-app/services/removable_drives.h"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace rockface::app {

namespace {

// /proc/mounts writes a space in a path as \040 (and tab, newline, backslash
// likewise): a stick labelled "FIELD DATA" mounts at /media/geo/FIELD\040DATA.
std::string unescape_mount_path(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\' && i + 3 < text.size() &&
        text.substr(i + 1, 3).find_first_not_of("01234567") == std::string::npos) {
      out += static_cast<char>(std::stoi(text.substr(i + 1, 3), nullptr, 8));
      i += 3;
      continue;
    }
    out += text[i];
  }
  return out;
}

bool removable_mount(const std::string& path) {
  return path.rfind("/media/", 0) == 0 || path.rfind("/run/media/", 0) == 0;
}

RemovableDrive stick(const std::filesystem::path& folder) {
  const std::string name = folder.filename().string();
  return {folder, "USB stick " + (name.empty() ? folder.string() : name)};
}

}  // namespace

std::vector<RemovableDrive> removable_drives(bool writable) {
  const int mode = writable ? W_OK : R_OK;
  std::vector<RemovableDrive> out;
  if (const char* dir = std::getenv("ROCKFACE_USB_DIR"); dir && *dir) {
    if (std::filesystem::is_directory(dir) && ::access(dir, mode) == 0) out.push_back(stick(dir));
    return out;
  }
  std::ifstream mounts("/proc/mounts");
  for (std::string line; std::getline(mounts, line);) {
    std::istringstream fields(line);
    std::string device, mount_point;
    if (!(fields >> device >> mount_point)) continue;
    const std::string path = unescape_mount_path(mount_point);
    if (removable_mount(path) && ::access(path.c_str(), mode) == 0) out.push_back(stick(path));
  }
  return out;
}

}  // namespace rockface::app
