#pragma once
// Temporary folders of a test binary (in /tmp: demo projects, screenshots,
// captured output) are removed when the binary's tests all pass, and kept
// when one fails, named on stderr at the end of the run so that a failure
// can be read. A suite registers each folder it makes, once.
#include <filesystem>

namespace rockface::test {

// Removes `dir` (and all it holds) at the end of the test program if every
// test passed; otherwise leaves it and prints where it is.
void remove_when_passed(const std::filesystem::path& dir);

}  // namespace rockface::test
