#pragma once
// The tunnel's files (docs/scene-extensions.md, "The tunnel's files"):
// - the alignment CSV, the surveyor's table: a header row naming the columns
//   chainage,easting,northing,elevation[,radius] (any order, case-insensitive,
//   comma or semicolon separated). With a radius column the rows are the
//   stations of a table of elements: row i's radius is that of the element
//   from row i to row i + 1 (+ right, - left, 0 or empty = straight; the last
//   row's radius empty or 0). Without it the rows are a dense polyline.
//   Lines starting with '#' and blank lines are skipped.
// - the design profile as JSON ({"format": "rockface-tunnel-profile/1", ...})
//   or CSV (one segment a row: kind,from_u,from_v,to_u,to_v,centre_u,centre_v,sense;
//   and optionally one row "ray_centre,u,v").
// Every bad file is refused with an InputError naming the file, the line (CSV)
// or field path (JSON), the field and the reason.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/tunnel/alignment.h"
#include "core/tunnel/design_profile.h"
#include "storage/tunnel/built_alignment.h"

namespace rockface::storage {

// The alignment table as read: stations, and per element its radius (only
// for a table of elements).
struct AlignmentTable {
  std::vector<tunnel::AlignmentStation> stations;
  std::vector<double> radii;  // stations.size() - 1 entries, or empty for a polyline
  bool polyline = true;
  // The alignment (checked: ordering, element lengths, radii). Errors name
  // `source` and the station's line when the table came from a file.
  // Built once per datum (built_alignment.h); a TunnelRecord made from the
  // table may share it.
  tunnel::Alignment build(const Eigen::Vector3d& datum, tunnel::Drive drive) const;
  std::string source;        // file name, for messages
  std::vector<int> line_of;  // per station: its line in the file (1-based)
  std::shared_ptr<BuiltAlignment> built = std::make_shared<BuiltAlignment>();
};

// The table is checked by building its alignment relative to check_datum
// (default: its first station): the datum it will be used with, so that
// the check's build is the one kept.
AlignmentTable read_alignment_csv(const std::filesystem::path& file,
                                  const std::optional<Eigen::Vector3d>& check_datum = std::nullopt);
AlignmentTable parse_alignment_csv(
    const std::string& text, const std::string& source,
    const std::optional<Eigen::Vector3d>& check_datum = std::nullopt);
std::string alignment_csv_text(const AlignmentTable& table);

// Both forms are checked with DesignProfile::validate() (the error names the
// file and segment).
tunnel::DesignProfile read_profile_json(const std::filesystem::path& file);
tunnel::DesignProfile parse_profile_json(const std::string& text, const std::string& source);
std::string profile_json_text(const tunnel::DesignProfile& profile);

tunnel::DesignProfile read_profile_csv(const std::filesystem::path& file);
tunnel::DesignProfile parse_profile_csv(const std::string& text, const std::string& source);
std::string profile_csv_text(const tunnel::DesignProfile& profile);

// By extension: .json or .csv (anything else is refused).
tunnel::DesignProfile read_profile_file(const std::filesystem::path& file);

}  // namespace rockface::storage
