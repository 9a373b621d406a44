#pragma once
// A project's tunnel from the surveyor's and the designer's files, without a
// scene (issue 42: a project got its tunnel only by replaying a scene): the
// alignment CSV and the design profile (JSON or CSV), as the scene's
// `tunnel` section takes them (docs/scene-extensions.md).
#include <filesystem>
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

// The whole of `rockface tunnel`, for the verb and the tablet's Project
// screen alike: the files read and checked before the project is opened for
// writing (a bad file leaves the project untouched), then stored. Throws
// InputError naming the file, option or project at fault.
struct GivenTunnel {
  storage::TunnelRecord record;
  std::string summary;  // "tunnel NAME, chainage A to B, N stations, profile X m²"
};
GivenTunnel give_project_its_tunnel(const std::filesystem::path& project, const TunnelFiles& files);

}  // namespace rockface::app
