#pragma once
// Small tablet projects for the office suite, and the checks that a server
// holds exactly what a tablet sent.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rockface::office_test {

// A set of planes a test designs along the drive (e.g. one that turns),
// beside the two families every visit measures: its mean dip / dip
// direction (degrees) at each visit, none where the visit does not see it.
// Six planes scattered about that mean as the others are (within 2 deg);
// at visit 0, whose sets are stored, the set is stored too, with the Fisher
// statistics of its planes.
struct DesignedSet {
  std::string label;  // its stored set's label at visit 0 ("S3", ...)
  std::vector<std::optional<std::array<double, 2>>> per_visit;
};

struct TabletProject {
  std::string name = "tablet";
  int visits = 2;
  double first_chainage = 102;  // visits 2.5 m apart along the sample tunnel
  int seed = 1;                 // varies photographs and plane scatter
  int image_width = 160, image_height = 120;
  bool dense_face_visit = false;  // one more visit: a mapped face with joints, for the analysis
  std::string tunnel = "Main drive";
  double underbreak_tolerance_m = 0.05;  // another value: the same tunnel, designed differently
  std::vector<DesignedSet> designed_sets;
};

// A project with the sample tunnel (tools/samples/tunnel-drive.*), and per
// visit: a capture (two JPEGs), its model, measured planes of two joint
// sets, a block analysis, its place in the tunnel; the first visit also
// joints and joint sets.
void make_tablet_project(const std::filesystem::path& file, const TabletProject& options);

// One more visit in a project make_tablet_project made with `options`:
// the one it would have made as visit number `v` (at first_chainage +
// 2.5 v), as a tablet adds a visit between two syncs.
void add_tablet_visit(const std::filesystem::path& file, const TabletProject& options, int v);

// Every row of the project's tables but the sync's own, as text: equal
// before and after a sync when the sync changed nothing else.
std::string project_content(const std::filesystem::path& file);

// The first line where two contents differ ("" when equal), for a short
// failure message.
std::string first_difference(const std::string& a, const std::string& b);

// The server (superuser connection) holds each record of the project as its
// latest revision (a record whose latest revision is its deletion is not
// held), with the same content; `revisions_each` revisions of
// every record when given; every photograph and mesh complete and hashing
// to its name. Adds GoogleTest failures.
void expect_server_holds(const std::string& superuser, const std::filesystem::path& project,
                         int revisions_each = 0);

}  // namespace rockface::office_test
