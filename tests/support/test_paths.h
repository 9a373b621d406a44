#pragma once
// Where the tests find the checkout, the build and ../shared/data. The paths
// are compiled into one small library (tests/support/test_paths.cpp) rather
// than into every test file: a test file then compiles to the same object in
// any clone of the project, so that the compiler cache of one checkout serves
// another (CI's fresh clone).
namespace rockface::test {
const char* source_dir();  // the checkout's root
const char* binary_dir();  // the build folder (rockface is there)
const char* shared_dir();  // ../shared beside the checkout
}  // namespace rockface::test

#define ROCKFACE_SOURCE_DIR (::rockface::test::source_dir())
#define ROCKFACE_BINARY_DIR (::rockface::test::binary_dir())
#define ROCKFACE_SHARED_DIR (::rockface::test::shared_dir())
