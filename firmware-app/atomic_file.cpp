#include "firmware-app/atomic_file.h"

#include <cstdio>
#include <fstream>

#include "core/common/error.h"

namespace rockface::app {

void write_atomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".part";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    f << text;
    f.flush();
    if (!f) {
      std::remove(tmp.c_str());
      throw Error(path + ": cannot write the file (disk full or no permission?)");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw Error(path + ": cannot write the file");
  }
}

}  // namespace rockface::app
