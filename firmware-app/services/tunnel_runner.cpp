// The tablet's tunnel views (ui::TunnelRunner): each opens its own
// connection to the project (one per thread) and draws what the verbs
// `profile` and `drive` write.

#include "core/common/number_format.h"
#include "firmware-app/services/ui_services.h"
#include "firmware-app/tunnel/project_drive.h"
#include "firmware-app/tunnel/typed_placement.h"
#include "firmware-app/tunnel/visit_profile.h"
#include "firmware-app/tunnel/visit_profile_json.h"
#include "storage/field_report/tunnel_pictures.h"
#include "storage/project/project_store.h"

namespace rockface::app {

namespace {

storage::ProjectStore open_read_only(const std::filesystem::path& project) {
  storage::OpenOptions read;
  read.read_only = true;
  return storage::ProjectStore::open(project, read);
}

}  // namespace

ui::TunnelPicture StoreTunnelRunner::profile(const std::filesystem::path& project,
                                             storage::RecordId visit_id, Progress& progress) {
  progress.step("excavation against the design", 0.1);
  storage::ProjectStore store = open_read_only(project);
  const VisitProfile p = visit_profile(store, visit_id);
  progress.step("developed view", 0.9);
  return {storage::developed_view_picture(p.deviation, p.tunnel.profile), visit_profile_summary(p)};
}

ui::TunnelPicture StoreTunnelRunner::drive(const std::filesystem::path& project,
                                           Progress& progress) {
  progress.step("sets along the drive", 0.1);
  storage::ProjectStore store = open_read_only(project);
  const tunnel::DriveSets d = project_drive(store);
  progress.step("drive picture", 0.9);
  return {storage::drive_picture(d), drive_summary(d)};
}

std::vector<std::string> StoreTunnelRunner::place(const std::filesystem::path& project,
                                                  storage::RecordId visit_id, double chainage,
                                                  double offset, double height,
                                                  Progress& progress) {
  progress.step("moving the 3D images to the typed chainage", 0.2);
  storage::ProjectStore store = storage::ProjectStore::open(project);
  const storage::VisitPlacement p =
      place_by_typed_chainage(store, visit_id, {chainage, offset, height});
  return {"visit " + std::to_string(static_cast<long long>(visit_id)) +
              " placed: face at chainage " + format_fixed(p.chainage, 2) + ", offset " +
              format_fixed(p.offset_m, 2, " m"),
          p.note};
}

}  // namespace rockface::app
