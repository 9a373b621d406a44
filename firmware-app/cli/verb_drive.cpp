// `rockface drive PROJECT --out DRIVE.png [--csv DRIVE.csv]`: each joint
// set's orientation along the tunnel's chainage over all visits, with the
// sets that appear, vanish or turn flagged. `rockface drive postgresql://...
// --tunnel NAME ...` gives the same from the office server, over every
// tablet's visits. `--support-csv` adds the support of each round (issue 44),
// from a server too (the tunnel pulled into a temporary project). The CSV's
// rows and the printed events name the geologist who mapped each visit.
#include <filesystem>
#include <iostream>
#include <memory>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/progress.h"
#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/office/office_workflows.h"
#include "firmware-app/support/support_drive.h"
#include "firmware-app/tunnel/project_drive.h"
#include "storage/exchange/image_file.h"
#include "storage/field_report/tunnel_pictures.h"
#include "storage/project/project_store.h"

namespace rockface::app {
namespace {

struct DriveOptions {
  std::string project, out, csv, tunnel, support_csv;
};

void write_support(const std::string& file, const std::vector<RoundSupport>& rounds) {
  write_text_atomically(file, drive_support_csv(rounds));
  for (const auto& line : drive_support_summary(rounds)) std::cout << line << "\n";
  std::cout << "support: " << file << "\n";
}

VerbRun setup_drive(CLI::App& sub) {
  auto o = std::make_shared<DriveOptions>();
  sub.add_option("PROJECT", o->project,
                 "project file (*.rockface) with a tunnel, or the office server (postgresql://... "
                 "or service=NAME) with --tunnel")
      ->required();
  sub.add_option("--tunnel", o->tunnel, "the server's tunnel (with a server)");
  sub.add_option("--out", o->out, "the sets against chainage, a PNG file")->required();
  sub.add_option("--csv", o->csv,
                 "one row per set and visit (the visit's geologist last), a CSV file");
  sub.add_option("--support-csv", o->support_csv,
                 "the support per round against the chainage (RMR89, Q, the class proposed "
                 "and decided), a CSV file; from a server, its tunnel is pulled first");
  return [o] {
    tunnel::DriveSets drive;
    DriveGeologists geologists;
    if (is_server_address(o->project)) {
      if (o->tunnel.empty()) throw InputError("--tunnel", "name the server's tunnel");
      const storage::office::ServerDrive records = server_drive_records(o->project, o->tunnel);
      drive = server_drive(records);
      geologists = server_drive_geologists(records);
      if (!o->support_csv.empty()) {
        NoProgress quiet;
        write_support(o->support_csv, server_drive_support(o->project, o->tunnel, quiet));
      }
    } else {
      if (!std::filesystem::exists(o->project))
        throw InputError(o->project, "no such project file");
      storage::OpenOptions read;
      read.read_only = true;
      storage::ProjectStore store = storage::ProjectStore::open(o->project, read);
      drive = project_drive(store);
      geologists = drive_geologists(store);
      if (!o->support_csv.empty()) write_support(o->support_csv, drive_support(store));
    }
    storage::write_image_file(o->out, storage::drive_picture(drive), ".png");
    if (!o->csv.empty()) write_text_atomically(o->csv, drive_csv(drive, geologists));
    for (const auto& line : drive_summary(drive, geologists)) std::cout << line << "\n";
    std::cout << "drive: " << o->out << "\n";
    return 0;
  };
}

const VerbRegistrar drive_verb{
    "drive",
    "the joint sets along the tunnel's drive: each set's orientation and Fisher K per visit "
    "against chainage, sets that appear, vanish or turn flagged",
    setup_drive};

}  // namespace
}  // namespace rockface::app
