#include "firmware-app/tunnel/tunnel_from_files.h"

#include <cmath>
#include <filesystem>

#include "core/common/error.h"
#include "storage/tunnel/tunnel_files.h"

namespace rockface::app {

storage::TunnelRecord tunnel_from_files(const TunnelFiles& f) {
  for (const auto& [file, option] :
       {std::pair{f.alignment, "--alignment"}, std::pair{f.profile, "--profile"}})
    if (!std::filesystem::is_regular_file(file))
      throw InputError(option, "no such file: " + (file.empty() ? std::string("(none)") : file));
  if (!(std::isfinite(f.underbreak_tolerance_m) && f.underbreak_tolerance_m >= 0 &&
        f.underbreak_tolerance_m <= 1))
    throw InputError("--underbreak-tolerance", "must be 0 to 1 m");
  storage::TunnelRecord rec;
  // Checked against the datum it is built with below (one build, kept).
  const storage::AlignmentTable table =
      storage::read_alignment_csv(f.alignment, Eigen::Vector3d::Zero());
  rec.stations = table.stations;
  rec.radii = table.radii;
  rec.polyline = table.polyline;
  rec.alignment_source = std::filesystem::path(f.alignment).filename().string();
  rec.profile = storage::read_profile_file(f.profile);
  rec.profile_source = std::filesystem::path(f.profile).filename().string();
  rec.drive = tunnel::drive_of(f.drive, "--drive");
  rec.underbreak_tolerance_m = f.underbreak_tolerance_m;
  rec.name = f.name.empty() ? std::filesystem::path(f.alignment).stem().string() : f.name;
  // The alignment is built once here so that a table it cannot take is
  // refused now, not at the first placement.
  table.build(Eigen::Vector3d::Zero(), rec.drive);
  return rec;
}

void give_project_its_tunnel(storage::ProjectStore& store, const storage::TunnelRecord& tunnel) {
  if (const auto has = store.load_tunnel())
    throw InputError(store.file().string(), "already has the tunnel " + has->name + " (alignment " +
                                                has->alignment_source +
                                                "); its visits are placed along it");
  store.save_tunnel(tunnel);
}

}  // namespace rockface::app
