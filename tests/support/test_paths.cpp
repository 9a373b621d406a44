#include "tests/support/test_paths.h"

namespace rockface::test {
// The build passes the paths as ROCKFACE_TEST_*_DIR (tests/CMakeLists.txt).
const char* source_dir() {
  return ROCKFACE_TEST_SOURCE_DIR;
}
const char* binary_dir() {
  return ROCKFACE_TEST_BINARY_DIR;
}
const char* shared_dir() {
  return ROCKFACE_TEST_SHARED_DIR;
}
}  // namespace rockface::test
