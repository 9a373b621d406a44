#pragma once
// What the screens need from above the UI layer. The analysis and the
// reconstruction are composed in firmware-app (the composition root), which
// the UI must not include; the screens call these interfaces on a worker
// thread (BackgroundTask) and firmware-app passes the implementations in.
//
// Every runner opens its own ProjectStore on the project file (one SQLite
// connection per thread), saves what it made as soon as it is made, and
// returns the id of the record.
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "camera/camera.h"
#include "core/analysis/block_verdict.h"
#include "core/analysis/support_decision.h"
#include "core/common/preset.h"
#include "core/common/progress.h"
#include "core/measure/compass_reading.h"
#include "core/measure/proposals/trace_proposals.h"
#include "core/rockmass/classification_form.h"
#include "storage/project/project_records.h"
#include "ui/app/import_runner.h"

namespace rockface::ui {

class ReconstructionRunner {
 public:
  virtual ~ReconstructionRunner() = default;
  // A textured, registered model of a stored capture at `preset`. Returns
  // the model's id.
  virtual storage::RecordId reconstruct(const std::filesystem::path& project,
                                        storage::RecordId capture_id, Preset preset,
                                        Progress& progress) = 0;
};

class AnalysisRunner {
 public:
  virtual ~AnalysisRunner() = default;
  // The block analysis of a visit's joints, traces and surface as stored.
  // Returns the analysis id.
  virtual storage::RecordId analyse(const std::filesystem::path& project,
                                    storage::RecordId visit_id, Progress& progress) = 0;
};

// The camera of the Capture screen: the DSLR when one is attached, else a
// mock camera (a replay folder or a synthetic scene).
class CameraConnector {
 public:
  virtual ~CameraConnector() = default;
  // Throws rockface::Error saying why no camera could be connected.
  virtual std::unique_ptr<camera::Camera> connect() = 0;
  // What connect() will try, e.g. "mock camera: synthetic scene tunnel-face".
  virtual std::string describe() const = 0;
};

// A picture with the lines that go with it (the tunnel's views).
struct TunnelPicture {
  cv::Mat bgr;
  std::vector<std::string> lines;
};

// Issue 39: the excavation of a visit's round for the Project screen, as
// figures and the developed view's cells (the field report's picture
// without its print-size labels), for the screen to write with the UI's
// units and its own font.
struct ExcavationPlace {
  std::string name;  // "crown", "right wall", ...
  double s_m = 0;    // along the design line from its start
};
struct ExcavationView {
  std::vector<std::string> lines;  // the round and the placement, in words
  bool compared = false;           // false: nothing to show, `message` says why
  std::string message;
  cv::Mat cells;  // BGR, the face at the top; `cells_margin_px` around
  int cells_margin_px = 0;
  double perimeter_m = 0;
  std::vector<ExcavationPlace> places;
  double chainage_bottom = 0, chainage_top = 0;  // of the first and last rows
  double scale_m = 0;                            // the colours' ± extent
  double tolerance_m = 0;                        // underbreak tolerance
  double overbreak_m3 = 0, underbreak_m3 = 0, seen_fraction = 0;
  std::optional<double> overbreak_sigma_m3, underbreak_sigma_m3;
  std::optional<double> deepest_underbreak_m, deepest_underbreak_chainage, deepest_underbreak_s_m;
  std::optional<double> largest_overbreak_m, largest_overbreak_chainage, largest_overbreak_s_m;
  int patches_beyond_tolerance = 0;
};

// Issue 39: the joints along the drive, for the Project screen to draw at
// the tablet's size: every placed visit's measured joints (dip and dip
// direction at its chainage), and the sets where the visits' joints form
// them (tracked along the drive as `rockface drive` tracks them).
struct DriveJointMark {
  storage::RecordId visit_id = 0;
  double chainage = 0;
  std::string label;  // "J1"
  double dip_deg = 0, dipdir_deg = 0;
};
struct DriveSetPoint {
  double chainage = 0, dip_deg = 0, dipdir_deg = 0;
  bool turned = false;  // turned beyond its cone here
};
struct DriveSetTrack {
  int id = 0;                         // 1, 2, ...: the colour
  std::vector<DriveSetPoint> points;  // in drive order
  std::string flags;                  // "new", "turns", "gone" in words; empty when none
};
struct DriveJoints {
  int visits = 0;  // placed in the tunnel
  std::vector<DriveJointMark> joints;
  std::vector<DriveSetTrack> sets;
  std::vector<std::string> lines;  // what `rockface drive` prints
};

// Issue 42: the files the geologist chose on the Project screen for the
// project's tunnel (from the tablet's storage or a USB stick), as `rockface
// tunnel` takes them.
struct TunnelFileChoice {
  std::filesystem::path alignment;  // the surveyor's CSV of stations
  std::filesystem::path profile;    // the design profile, JSON or CSV
  std::string name;                 // empty: the alignment file's stem
};

// The tunnel around the visits: the project's tunnel from its files, the
// excavation of a visit's round against the design profile, and the joint
// sets along the drive.
class TunnelRunner {
 public:
  virtual ~TunnelRunner() = default;
  // Gives the project its tunnel by the workflow `rockface tunnel` runs;
  // returns what was stored in words. Throws InputError as the command line
  // says it (the file and line at fault, a project that has a tunnel), the
  // project unchanged.
  virtual std::string give_tunnel(const std::filesystem::path& project,
                                  const TunnelFileChoice& files, Progress& progress) = 0;
  // Throw rockface::Error / InputError saying why (no tunnel, visit not placed).
  virtual ExcavationView profile(const std::filesystem::path& project, storage::RecordId visit_id,
                                 Progress& progress) = 0;
  virtual DriveJoints drive(const std::filesystem::path& project, Progress& progress) = 0;
  // Places the visit by the chainage, offset and height (m above the axis)
  // the geologist typed for the range pole's lower target; returns what was
  // placed in words.
  virtual std::vector<std::string> place(const std::filesystem::path& project,
                                         storage::RecordId visit_id, double chainage, double offset,
                                         double height, Progress& progress) = 0;
};

// The blocks of a visit's trace map while the geologist maps it (issue 28):
// after each saved trace the Mapping screen shows which loops of traces are
// blocks and what they do, before the full analysis of the Blocks screen.
// Only the block-theory verdicts and the limit-equilibrium mode and factor of
// safety: the costly parts (rotation, remote axis, mechanics) stay with the
// full analysis.
struct MapBlock {
  std::vector<Eigen::Vector3d> outline;  // the loop on the surface, absolute, m
  analysis::BlockVerdict verdict = analysis::BlockVerdict::infinite;
  std::string mode;  // "falling" | "lifting" | "sliding" | "none", as the stored analysis
  std::optional<double> factor_of_safety;
  double margin_deg = 0;  // of the deciding verdict (finiteness, else removability)
  double volume_m3 = 0;   // finite blocks
};

struct MapVerdicts {
  std::vector<MapBlock> blocks;
  int traces = 0;                  // traces on the map (joined pieces count once)
  int recomputed = 0;              // regions computed by this update
  int reused = 0;                  // regions whose block the last update had
  double milliseconds = 0;         // from the traces to the verdicts, wall
  std::vector<std::string> notes;  // what the map left out, in words
};

// Issue 27: one edit of the Mapping screen. The measuring runs on the
// worker over the model the screen holds (no second load).
struct MapEdit {
  storage::RecordId visit_id = 0;
  const measure::MeshPicker* picker = nullptr;  // the 3D image on display (face frame)
  std::optional<storage::RecordId> model_id;    // its model: a trace of another pair's is
                                                // measured on that pair's 3D image (issue 27)
  measure::MeasureSettings settings;            // its point precision
  // A trace to store: its points, photograph pixels, model, joint, origin.
  std::optional<storage::Measurement> trace;
  // The face's outline: its corners in the left photograph (the one the
  // model is textured with, seen through `view`), split by the runner into
  // the flat pieces of the 3D image it covers (core/measure/outline_pieces.h),
  // each measured as `rockface measure` measures an area pick, and stored
  // as the visit's mapped face in place of the one stored; with that
  // photograph's model and capture. Empty: no outline.
  std::vector<Eigen::Vector2d> outline;
  const measure::PhotoView* view = nullptr;
  std::optional<storage::RecordId> outline_model_id, outline_capture_id;
  std::optional<storage::RecordId> remove_trace;  // a stored trace taken back
  // Issue 27: a compass reading given (or, with `compass` empty, cleared)
  // for the stored trace `compass_trace`: its plane and joint remade. A trace
  // to store (`trace`) carries its reading in its compass fields.
  std::optional<storage::RecordId> compass_trace;
  std::optional<measure::CompassReading> compass;
};

class TraceMapRunner {
 public:
  virtual ~TraceMapRunner() = default;
  // The verdicts of the visit's stored traces as they are now. The runner
  // keeps the map of the last call (one visit at a time) and recomputes only
  // the regions an edit touched. Throws rockface::Error / InputError saying
  // why (no surface patches, a bad trace).
  virtual MapVerdicts update(const std::filesystem::path& project, storage::RecordId visit_id,
                             Progress& progress) = 0;
  // Issue 27: stores an edit of the map (MapEdit) as `rockface measure`
  // stores picks, then remakes the visit's joint table from its traces as
  // the verb makes it; returns what was stored in words. Throws
  // rockface::InputError naming what is wrong (a degenerate outline).
  virtual std::string store(const std::filesystem::path& project, const MapEdit& edit,
                            Progress& progress) = 0;
};

// The wedges around the excavation (issue 23) for the Blocks screen's
// Wedges view: the wedges of the project's tunnel with a visit's sets, as
// a table already in words and units, with the section picture.
struct WedgeTable {
  std::vector<std::string> lines;    // the input: section, axis, sets, effects
  std::vector<std::string> columns;  // headings with units
  std::vector<std::vector<std::string>> rows;
  std::vector<bool> marginal;      // per row: a verdict inside the uncertainty
  std::vector<std::string> notes;  // corners crossed, pyramids with no wedge, assumptions
  cv::Mat bgr;                     // the section and the largest wedges
};

// Issue 39: the Wedges view's form, the options `rockface wedges --friction
// --bolts --shotcrete` takes, in the units a geologist types them. Empty:
// not given (the joints' own friction, else the default; no support).
struct WedgeBoltsForm {
  double length_m = 0, spacing_m = 0, capacity_kn = 0;
};
struct WedgeShotcreteForm {
  double thickness_mm = 0, shear_strength_mpa = 0;
};
struct WedgeForm {
  std::optional<double> friction_deg;
  std::optional<WedgeBoltsForm> bolts;
  std::optional<WedgeShotcreteForm> shotcrete;
};

class WedgeRunner {
 public:
  virtual ~WedgeRunner() = default;
  // Throws rockface::InputError saying why (no tunnel, fewer than three sets
  // and joints, a form value out of its range named by its option).
  virtual WedgeTable wedges(const std::filesystem::path& project, storage::RecordId visit_id,
                            const WedgeForm& form, Progress& progress) = 0;
};

// The office server (issue 24): the tablet's one server (a libpq service
// set once per tablet), what waits to go up, and the sync itself.
struct SyncOverview {
  std::string server;  // e.g. "service=rockface"; never a password
  bool ever_synced = false;
  std::string tunnel, last_sync_at, last_outcome;
  int records_waiting = 0, visits_waiting = 0;
};

class SyncRunner {
 public:
  virtual ~SyncRunner() = default;
  // Read from the project alone (no network).
  virtual SyncOverview overview(const std::filesystem::path& project) = 0;
  // Sends what waits; returns what was sent in words. Throws rockface::Error
  // saying so when the server cannot be reached (nothing lost: the next
  // sync resumes), Cancelled when cancelled (likewise).
  virtual std::vector<std::string> sync(const std::filesystem::path& project,
                                        Progress& progress) = 0;
};

// The rock mass of a visit (issue 23): its figures and classifications in
// words, with the form entered for it (saved first when given).
class RockMassRunner {
 public:
  virtual ~RockMassRunner() = default;
  // Throws InputError naming the field for a form value out of range, or
  // the visit when it has no traces.
  virtual std::vector<std::string> figures(const std::filesystem::path& project,
                                           storage::RecordId visit_id,
                                           const std::optional<rockmass::ClassificationForm>& save,
                                           Progress& progress) = 0;
};

// Trace proposals (issue 25) for the Mapping screen: the lines of the 3D
// image on display that look like joint traces (folds of the surface, dark
// lines of its photograph), each measured like a hand trace, with its
// confidence, for the geologist to accept, correct or reject. Runs on the
// worker over the model the screen already holds (no second load).
struct ProposalInput {
  const photogrammetry::SurfaceMesh* mesh = nullptr;
  const measure::MeshPicker* picker = nullptr;  // on `mesh`
  const measure::PhotoView* view = nullptr;     // the left photograph's camera and pose
  cv::Mat photo;                                // that photograph (BGR)
  double point_sigma_m = 0.01;                  // the model's depth precision (1 sigma)
  Preset preset = Preset::standard;
};

class ProposalRunner {
 public:
  // Called on the worker with each batch of proposals as it is measured
  // (issue 45: the first within 2 s, the rest as they come): unnamed, not
  // linked to a facet, each one of the result's (the same points).
  using Batch = std::function<void(const std::vector<measure::TraceProposal>&)>;
  virtual ~ProposalRunner() = default;
  // Throws InputError saying why (no photograph, a mesh without lattice);
  // Cancelled when cancelled. `batch` may be empty.
  virtual measure::ProposalResult propose(const ProposalInput& input, Progress& progress,
                                          const Batch& batch) = 0;
};

// Issue 27: the field report of a visit, written from the tablet (the
// Blocks screen's "Field report"), as `rockface report` writes it.
class FieldReportRunner {
 public:
  virtual ~FieldReportRunner() = default;
  // Writes the PDF; returns what it holds in words ("3 blocks, 2 joints").
  // Throws rockface::Error saying why (no such visit, cannot write).
  virtual std::string write(const std::filesystem::path& project, storage::RecordId visit_id,
                            const std::filesystem::path& pdf, Progress& progress) = 0;
};

// Issue 43: a visit's exports for the office's tools (`rockface export`:
// OBJ / PLY, DXF, CSV) onto a USB stick, from the Blocks and Project screens.
struct ExportTarget {
  std::filesystem::path folder;  // where the export's own folder is made
  std::string label;             // what the tablet shows ("USB stick KINGSTON")
};
class ExportRunner {
 public:
  virtual ~ExportRunner() = default;
  // The removable drives mounted now (a USB stick); empty when none is.
  virtual std::vector<ExportTarget> targets() = 0;
  // Every item the visit has into a folder made on `target`; returns what
  // was written in words. Throws rockface::Error saying why.
  virtual std::string write(const std::filesystem::path& project, storage::RecordId visit_id,
                            const ExportTarget& target, Progress& progress) = 0;
};

// North given after the visit (issue 42): the compass line's two pixels in
// the left photograph of the visit's first pair and the bearing the
// geologist read along it turn the visit's 3D images about the vertical
// (the workflow `rockface orient` runs). Returns what was done in words;
// throws rockface::Error naming the visit or the line.
class NorthRunner {
 public:
  virtual ~NorthRunner() = default;
  virtual std::string orient(const std::filesystem::path& project, storage::RecordId visit_id,
                             const Eigen::Vector2d& from_px, const Eigen::Vector2d& to_px,
                             double bearing_deg, double declination_deg, Progress& progress) = 0;
};

// A visit imported in a local frame scaled and levelled by the range pole's
// two targets tapped on its 3D view (issue 43; the workflow of
// firmware-app/import/scale_import_by_pole.h): `lower` and `upper` are
// points of the 3D image as stored. Returns what was done in words; throws
// rockface::Error naming the visit or the pole.
class PoleRunner {
 public:
  virtual ~PoleRunner() = default;
  virtual std::string scale(const std::filesystem::path& project, storage::RecordId visit_id,
                            const Eigen::Vector3d& lower, const Eigen::Vector3d& upper,
                            double length_m, Progress& progress) = 0;
};

// Issue 44 on the tablet: the round's support (the workflow `rockface
// support` runs): what the Q chart, Bieniawski's table and the designer's
// classes propose for the visit, side by side, the checks on its wedges and
// moving blocks, and the decision stored with the visit.
struct SupportChoice {
  std::string class_name, by;
  std::string reason;                            // required when the class is not the proposed one
  std::vector<analysis::SupportChange> changes;  // each with what, from, to and why
};
struct SupportDecided {
  std::string class_name, proposed, reason, by, at, checks;
  std::vector<analysis::SupportChange> changes;
};
struct SupportProposals {
  std::string figures;  // "Visit 1 at chainage 111.73 m: RMR89 62, Q 4.2"
  std::vector<std::string> from_q, from_rmr, from_classes;  // each proposal in words
  std::vector<std::string> classes;  // the designer's classes, lightest first
  std::string proposed;              // the class proposed; empty: none
  std::vector<std::string> checks;   // the checks in words
  // The pattern as decided (the chosen class with the decision's changes):
  // its check in words, then what of the changes the check does not use;
  // empty when the decision changes nothing.
  std::vector<std::string> decided_check;
  std::optional<SupportDecided> decision;  // the stored one (the latest)
  std::vector<std::string> notes;
};

class SupportRunner {
 public:
  virtual ~SupportRunner() = default;
  // The proposals and the stored decision; with `decide`, the decision is
  // made and stored first. Throws InputError naming what is wrong (a class
  // not of the tunnel, no reason for a class other than the proposed one).
  virtual SupportProposals support(const std::filesystem::path& project, storage::RecordId visit_id,
                                   const std::optional<SupportChoice>& decide,
                                   Progress& progress) = 0;
};

struct FieldServices {
  ReconstructionRunner* reconstruction = nullptr;  // null: the Model screen cannot reconstruct
  AnalysisRunner* analysis = nullptr;              // null: the Blocks screen cannot analyse
  CameraConnector* camera = nullptr;               // null: no camera
  TunnelRunner* tunnel = nullptr;                  // null: the Project screen shows no tunnel views
  TraceMapRunner* trace_map = nullptr;             // null: the Mapping screen shows no blocks
  WedgeRunner* wedges = nullptr;                   // null: the Blocks screen shows no Wedges view
  SyncRunner* sync = nullptr;                      // null: no office server on this tablet
  RockMassRunner* rockmass = nullptr;              // null: the Blocks screen shows no rock mass
  ProposalRunner* proposals = nullptr;             // null: the Mapping screen proposes no traces
  // Issue 27.
  FieldReportRunner* field_report = nullptr;  // null: no Field report button
  // Issue 43.
  ExportRunner* exports = nullptr;  // null: no Export to USB stick button
  // Issue 42.
  NorthRunner* north = nullptr;  // null: the Model screen gives no north
  // Issue 44.
  SupportRunner* support = nullptr;  // null: the Blocks screen shows no Support view
  ImportRunner* imports = nullptr;   // null: no Import a 3D image (issue 43)
  PoleRunner* pole = nullptr;        // null: an imported cloud is not scaled on the tablet (43)
};

}  // namespace rockface::ui
