#pragma once
// ProjectStore: one rockface project = one SQLite file (*.rockface) holding
// everything of a site: project and datum, cameras and calibrations, captures
// with their images, models, measurements, joints, block analyses and a log of
// what was done when. Copying that one file moves the project.
//
// Safety rules it keeps:
// - Every save is one transaction (all of it or nothing), durable when the
//   call returns (WAL, synchronous = FULL): a flat battery right after a save
//   loses nothing, one during a save loses only that save.
// - Opening checks before it writes: the file is opened read-only first, its
//   application_id, schema version and integrity are checked, and only a
//   healthy project of a known version is reopened for writing. A foreign or
//   damaged file is never written to.
// - A project of a newer schema opens read-only, and read_only_reason() says why.
// - Errors are rockface::Error / InputError naming the file and the reason.
//
// Threads: one ProjectStore per thread (one SQLite connection each). A UI
// thread and a worker open two stores on the same file; readers see the last
// committed state and never wait for a writer (WAL); writers queue behind each
// other for up to busy_timeout instead of failing with "database is locked".
// Two programs on one project (`rockface ui` and a verb run beside it, the
// office sync) are serialised the same way by SQLite's file locks; a writer
// that waits past busy_timeout stops with nothing saved and says so. The
// file is read only through SQLite while a store may be open in the process
// (check_header in project_store.cpp says why: a second descriptor's close
// drops the process's locks, and another program then deletes the
// write-ahead log in use here).
#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/analysis/support_classes.h"
#include "core/analysis/support_decision.h"
#include "core/rockmass/classification_form.h"
#include "storage/project/project_integrity.h"
#include "storage/project/project_records.h"
#include "storage/project/project_sqlite.h"
#include "storage/tunnel/tunnel_records.h"

namespace rockface::storage {

struct OpenOptions {
  bool read_only = false;
  // How thoroughly to check the file when opening
  // (storage/project/project_integrity.h): quick reads every page, full runs
  // integrity_check, rows leaves the photographs' and 3D images' pages to
  // be checked as they are read (the tablet: it checks the whole file on a
  // worker after opening).
  using Check = IntegrityDepth;
  Check check = Check::quick;
  // How long a write waits for another connection's write to finish.
  std::chrono::milliseconds busy_timeout{30000};
  // Refuse to grow the file beyond this many bytes (keep room on the card
  // for the camera); 0 = no limit. A save that would pass it fails cleanly.
  std::int64_t max_file_bytes = 0;
  // Name of a registered SQLite VFS (fault-injection tests); empty = default.
  std::string vfs;
};

class ProjectStore {
 public:
  // A new project; fails if the file exists. The file appears complete or not
  // at all (built under a temporary name beside it, then linked into place).
  static ProjectStore create(const std::filesystem::path& file, const ProjectInfo& info,
                             const OpenOptions& options = {});
  // An existing project; see the class comment for the checks.
  static ProjectStore open(const std::filesystem::path& file, const OpenOptions& options = {});
  // open() if the file exists, else create() with `info`.
  static ProjectStore open_or_create(const std::filesystem::path& file, const ProjectInfo& info,
                                     const OpenOptions& options = {});

  ProjectStore(ProjectStore&&) noexcept;
  ProjectStore& operator=(ProjectStore&&) noexcept;
  ~ProjectStore();

  const std::filesystem::path& file() const { return file_; }
  bool read_only() const { return read_only_; }
  // Why the project is read-only ("opened read-only on request", "written by
  // a newer rockface ..."); empty when writable.
  const std::string& read_only_reason() const { return read_only_reason_; }
  int schema_version() const { return schema_version_; }

  ProjectInfo project();
  void update_project(const ProjectInfo& info);

  // Runs `body` (saves of this store) as one transaction: everything it
  // saves is stored, or nothing when it throws (an import that fails half-way
  // leaves the project as it was).
  void in_one_transaction(const std::string& doing, const std::function<void()>& body);

  // A new visit every call (running replay twice gives two visits), with
  // the geologist who maps it ("" none; checked_geologist, InputError naming
  // "geologist" before anything is stored).
  RecordId begin_visit(const std::string& source, const std::string& note = {},
                       const std::string& geologist = {});
  // Names the geologist who mapped a visit ("" takes the name away; the
  // name checked as begin_visit's). InputError naming the visit for an
  // unknown one.
  void save_visit_geologist(RecordId visit_id, const std::string& geologist);
  // None when the visit has no geologist.
  std::optional<std::string> load_visit_geologist(RecordId visit_id);
  std::vector<Visit> list_visits();
  std::optional<RecordId> latest_visit();

  // The body with the same (make, model, serial) if stored, else a new one.
  RecordId save_camera_body(const CameraBody& body);
  std::vector<CameraBody> list_camera_bodies();
  // An identical calibration (same body, values, provenance) already stored
  // is returned instead of a copy.
  RecordId save_calibration(const Calibration& calibration);
  Calibration load_calibration(RecordId id);
  std::vector<Calibration> list_calibrations();

  // Image formats are detected from the bytes (JPEG or PNG; anything else is
  // an InputError). Identical image bytes are stored once.
  RecordId save_capture(const Capture& capture);
  Capture load_capture(RecordId id);
  std::vector<CaptureSummary> list_captures(std::optional<RecordId> visit_id = {});
  // A setting of the project's newest capture that has it (the range pole's
  // length the geologist typed, issue 42), without loading its images.
  std::optional<std::string> latest_capture_setting(const std::string& key);
  // The encoded bytes of one image of a capture ("left" | "right").
  ImageBlob load_capture_image(RecordId capture_id, const std::string& side);

  RecordId save_model(const Model& model);
  Model load_model(RecordId id);
  std::vector<ModelSummary> list_models(std::optional<RecordId> capture_id = {});
  // The 3D images of one visit, one per stereo pair in the order the pairs
  // were taken (capture order; a capture with several models gives its
  // latest): the first pair's mesh frame is the face frame, a further pair's
  // model is registered onto it (`rockface replay` of several pairs).
  std::vector<ModelSummary> list_visit_models(RecordId visit_id);

  // Saves traces, areas and point orientations of one visit in one
  // transaction; returns their ids in order.
  std::vector<RecordId> save_measurements(RecordId visit_id,
                                          const std::vector<Measurement>& measurements);
  std::vector<Measurement> list_measurements(std::optional<RecordId> visit_id = {});

  // Saves joint sets and the joints that name them (Joint::set_label) in one
  // transaction; returns the joint ids in order. Labels are unique per visit.
  std::vector<RecordId> save_joints(RecordId visit_id, const std::vector<JointSet>& sets,
                                    const std::vector<Joint>& joints);
  std::vector<JointSet> list_joint_sets(RecordId visit_id);
  std::vector<Joint> list_joints(std::optional<RecordId> visit_id = {});

  // ---- deletions (issue 27: undo on the tablet; storage/project/project_store_deletions.cpp) ----
  // A change is a new row; these remove rows the geologist took back. A
  // removed row goes to the office as a deleted revision on the next sync
  // (storage/office: the sync compares the rows with what it sent).
  // Deletes one measurement and the joints fitted from it, in one
  // transaction; InputError when there is no such measurement.
  void delete_measurement(RecordId measurement_id);
  // Issue 27: a stored trace's plane as measured again with its compass
  // reading given or cleared (`measured`: its dip, dip direction, sigma, fit
  // RMS, note and compass fields), in place: the trace keeps its id and
  // UUID (the office gets a new revision of it). Logged; InputError when
  // there is no such trace or the values are not an orientation.
  void set_trace_plane(RecordId measurement_id, const Measurement& measured);
  // Deletes joints and joint sets of one visit, in one transaction;
  // InputError naming the row when one is not the visit's, or when a set to
  // delete is still named by a joint that stays.
  void delete_joints(RecordId visit_id, const std::vector<RecordId>& joint_ids,
                     const std::vector<RecordId>& set_ids);

  // One block analysis with its preset, effects and every block, in one
  // transaction.
  RecordId save_analysis(const AnalysisRun& run);
  AnalysisRun load_analysis(RecordId id);
  std::vector<AnalysisRun> list_analyses(std::optional<RecordId> visit_id = {});  // no blocks

  // An action that saves nothing else (an export, a deletion request, a UI
  // step worth remembering). Every save_* above logs itself.
  RecordId log_action(std::optional<RecordId> visit_id, const std::string& action,
                      const std::string& detail = {});
  std::vector<ActionLogEntry> list_actions(std::optional<RecordId> visit_id = {});

  // ---- the tunnel (issue 22; storage/project/project_store_tunnel.cpp) ----
  // The project's tunnel: saving replaces the one stored (alignment table,
  // profile and all), in one transaction; the profile must validate and the
  // alignment build with the project's datum (InputError naming the field).
  void save_tunnel(const TunnelRecord& tunnel);
  std::optional<TunnelRecord> load_tunnel();
  // A visit's place in the tunnel; saving again replaces it.
  void save_visit_placement(const VisitPlacement& placement);
  std::optional<VisitPlacement> load_visit_placement(RecordId visit_id);
  std::vector<VisitPlacement> list_visit_placements();  // by chainage

  // ---- the rock-mass form (issue 23; storage/project/project_store_rockmass.cpp) ----
  // The classification form entered for a visit: saving replaces the one
  // stored (validated first: an out-of-range value is refused by name).
  void save_rockmass_form(RecordId visit_id, const rockmass::ClassificationForm& form);
  std::optional<rockmass::ClassificationForm> load_rockmass_form(RecordId visit_id);

  // ---- the support of the rounds (issue 44; storage/project/project_store_support.cpp) ----
  // The tunnel's support classes: each save adds a revision, the latest is
  // in force. A visit's support decision likewise (the earlier decisions
  // stay, in order). InputError naming the visit for an unknown one.
  void save_support_classes(const analysis::SupportClasses& classes);
  std::optional<analysis::SupportClasses> load_support_classes();
  void save_support_decision(RecordId visit_id, const analysis::SupportDecision& decision);
  std::optional<analysis::SupportDecision> load_support_decision(RecordId visit_id);
  std::vector<analysis::SupportDecision> list_support_decisions(RecordId visit_id);  // oldest first

  IntegrityReport check_integrity(OpenOptions::Check depth = OpenOptions::Check::full);
  // A whole-file check made after opening (on another connection) found
  // the file damaged: nothing more is saved to it; the reason says why.
  void stop_writing(std::string reason);
  // Moves the write-ahead log into the main file (done on close anyway); a
  // file copied after this is complete on its own.
  void checkpoint();

 private:
  ProjectStore(std::filesystem::path file, sqlite::Connection db, bool read_only,
               std::string read_only_reason, int schema_version);
  void require_writable(const std::string& doing) const;
  RecordId insert_log(std::optional<RecordId> visit_id, const std::string& action,
                      const std::string& detail);
  RecordId store_image(const ImageBlob& image, const std::string& where);
  // Inside the caller's write transaction: the visit's geologist row
  // (a checked, non-empty name) and its log line.
  void put_visit_geologist(RecordId visit_id, const std::string& name, const std::string& doing);

  std::filesystem::path file_;
  sqlite::Connection db_;
  bool read_only_ = false;
  std::string read_only_reason_;
  int schema_version_ = 0;
  // Device and inode of the file when opened. In WAL mode SQLite keeps
  // writing through its open descriptor after the file was renamed or
  // deleted (a delete would lose every later save on close), so each save
  // first checks that the path still names this file.
  std::uint64_t device_ = 0, inode_ = 0;
};

// Current UTC time as ISO 8601 with milliseconds ("2026-11-21T05:20:11.123Z").
std::string utc_now_iso8601();

}  // namespace rockface::storage
