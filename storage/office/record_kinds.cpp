#include "storage/office/record_kinds.h"

namespace rockface::storage::office {

const std::vector<RecordKind>& record_kinds() {
  static const std::vector<RecordKind> kinds = {
      {"project", "t.uuid", "NULL", "t.id", {}, {}},
      {"camera_body", "t.uuid", "NULL", "t.id", {}, {}},
      {"calibration", "t.uuid", "NULL", "t.id", {}, {}},
      {"tunnel",
       "(SELECT uuid FROM project WHERE id = 1)",
       "NULL",
       "t.id",
       {{"tunnel_station", "tunnel_id"}, {"tunnel_profile_segment", "tunnel_id"}},
       {}},
      // The tunnel's support classes (issue 44): every revision, the latest
      // in force.
      {"support_classes", "t.uuid", "NULL", "t.id", {}, {}},
      {"visit", "t.uuid", "t.id", "t.id", {}, {}},
      // An image shared by several captures goes with the first visit that
      // took it.
      {"image",
       "t.uuid",
       "(SELECT min(c.visit_id) FROM capture c WHERE c.left_image_id = t.id OR "
       "c.right_image_id = t.id)",
       "t.id",
       {},
       {"bytes"}},
      {"capture",
       "t.uuid",
       "t.visit_id",
       "t.id",
       {{"capture_setting", "capture_id"}, {"capture_exif", "capture_id"}},
       {}},
      {"model",
       "t.uuid",
       "(SELECT c.visit_id FROM capture c WHERE c.id = t.capture_id)",
       "t.id",
       {{"registration_residual", "model_id"}},
       {"mesh"}},
      {"measurement", "t.uuid", "t.visit_id", "t.id", {}, {}},
      {"joint_set", "t.uuid", "t.visit_id", "t.id", {}, {}},
      {"joint", "t.uuid", "t.visit_id", "t.id", {}, {}},
      {"analysis", "t.uuid", "t.visit_id", "t.id", {}, {}},
      {"block",
       "t.uuid",
       "(SELECT a.visit_id FROM analysis a WHERE a.id = t.analysis_id)",
       "t.id",
       {},
       {}},
      {"visit_placement",
       "(SELECT v.uuid FROM visit v WHERE v.id = t.visit_id)",
       "t.visit_id",
       "t.visit_id",
       {{"visit_placement_residual", "visit_id"}},
       {}},
      // The rock-mass form entered for a visit (issue 23), one per visit.
      {"rockmass_form",
       "(SELECT v.uuid FROM visit v WHERE v.id = t.visit_id)",
       "t.visit_id",
       "t.visit_id",
       {},
       {}},
      // The heading a visit was taken at (issue 46), one per named visit;
      // a visit whose name is taken away is deleted here, as a record.
      {"visit_heading",
       "(SELECT v.uuid FROM visit v WHERE v.id = t.visit_id)",
       "t.visit_id",
       "t.visit_id",
       {},
       {}},
      // The geologist who mapped a visit (issue 46), one per visit with a
      // name; a name taken away is deleted here, as a record.
      {"visit_geologist",
       "(SELECT v.uuid FROM visit v WHERE v.id = t.visit_id)",
       "t.visit_id",
       "t.visit_id",
       {},
       {}},
      // A visit's support decisions (issue 44), every revision.
      {"support_decision", "t.uuid", "t.visit_id", "t.id", {}, {}},
      {"action_log", "t.uuid", "t.visit_id", "t.id", {}, {}},
  };
  return kinds;
}

const RecordKind* find_record_kind(const std::string& kind) {
  for (const auto& k : record_kinds())
    if (kind == k.kind) return &k;
  return nullptr;
}

}  // namespace rockface::storage::office
