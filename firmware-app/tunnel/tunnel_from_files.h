#pragma once
// A project's tunnel from the surveyor's and the designer's files, without a
// scene (issue 42: a project got its tunnel only by replaying a scene): the
// alignment CSV and the design profile (JSON or CSV), as the scene's
// `tunnel` section takes them (docs/scene-extensions.md).
#include <string>

#include "storage/project/project_store.h"
#include "storage/tunnel/tunnel_records.h"

namespace rockface::app {

struct TunnelFiles {
  std::string alignment, profile;  // files
  std::string name;                // empty: the alignment file's stem
  std::string drive = "ascending";
  double underbreak_tolerance_m = 0.05;
};

// Throws InputError naming the file or option at fault.
storage::TunnelRecord tunnel_from_files(const TunnelFiles& files);

// Stores it in the project. A project that has a tunnel keeps it: refused
// naming it (its visits are placed along that alignment).
void give_project_its_tunnel(storage::ProjectStore& store, const storage::TunnelRecord& tunnel);

}  // namespace rockface::app
