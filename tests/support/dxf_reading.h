#pragma once
// A DXF read by an independent reader: ezdxf (Debian's python3-ezdxf), run
// on tests/support/read_dxf.py, which prints the layers and every POLYLINE
// (3D polylines with their points, polyface meshes with their vertices and
// faces) as JSON. For the export tests (issue 43).
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/cli_run.h"
#include "tests/support/test_paths.h"

namespace rockface::test {

struct DxfReading {
  int exit_code = -1;
  std::string output;      // the reader's output (its error when it failed)
  nlohmann::json drawing;  // {"layers": [...], "entities": [...]} when it read the file
};

inline DxfReading read_dxf(const std::filesystem::path& file) {
  // Debian's python3, which has python3-ezdxf (a python3 earlier on PATH,
  // such as a pyenv shim, would not).
  const CliRun run = run_command("/usr/bin/python3 " + std::string(ROCKFACE_SOURCE_DIR) +
                                 "/tests/support/read_dxf.py " + file.string());
  DxfReading r;
  r.exit_code = run.exit_code;
  r.output = run.out;
  if (r.exit_code == 0) r.drawing = nlohmann::json::parse(r.output, nullptr, false);
  return r;
}

}  // namespace rockface::test
