#pragma once
// The tablet UI's runners (ui/app/field_services.h) composed from the parts the
// UI layer must not include: reconstruction with registration, the scene
// analysis, and the cameras (the DSLR, or the mock camera of a scene or a
// capture folder).
#include <memory>
#include <optional>
#include <string>

#include "ui/app/field_services.h"

namespace rockface::app {

class StoreReconstructionRunner final : public ui::ReconstructionRunner {
 public:
  storage::RecordId reconstruct(const std::filesystem::path& project, storage::RecordId capture_id,
                                Preset preset, Progress& progress) override;
};

class StoreAnalysisRunner final : public ui::AnalysisRunner {
 public:
  storage::RecordId analyse(const std::filesystem::path& project, storage::RecordId visit_id,
                            Progress& progress) override;
};

class StoreTunnelRunner final : public ui::TunnelRunner {
 public:
  std::string give_tunnel(const std::filesystem::path& project, const ui::TunnelFileChoice& files,
                          Progress& progress) override;
  ui::ExcavationView profile(const std::filesystem::path& project, storage::RecordId visit_id,
                             Progress& progress) override;
  ui::DriveJoints drive(const std::filesystem::path& project, Progress& progress) override;
  std::vector<std::string> place(const std::filesystem::path& project, storage::RecordId visit_id,
                                 double chainage, double offset, double height,
                                 Progress& progress) override;
};

// The Mapping screen's blocks: keeps the last visit's trace map between
// calls (one visit at a time; the worker calls it, one task at a time).
class StoreTraceMapRunner final : public ui::TraceMapRunner {
 public:
  StoreTraceMapRunner();
  ~StoreTraceMapRunner() override;
  ui::MapVerdicts update(const std::filesystem::path& project, storage::RecordId visit_id,
                         Progress& progress) override;
  std::string store(const std::filesystem::path& project, const ui::MapEdit& edit,
                    Progress& progress) override;

 private:
  struct Cache;
  std::unique_ptr<Cache> cache_;
};

class StoreWedgeRunner final : public ui::WedgeRunner {
 public:
  ui::WedgeTable wedges(const std::filesystem::path& project, storage::RecordId visit_id,
                        const ui::WedgeForm& form, Progress& progress) override;
};

// The tablet's sync to the office server named by its libpq service
// (firmware-app/office/office_workflows.h tablet_server()).
class StoreSyncRunner final : public ui::SyncRunner {
 public:
  ui::SyncOverview overview(const std::filesystem::path& project) override;
  std::vector<std::string> sync(const std::filesystem::path& project, Progress& progress) override;
};

class StoreRockMassRunner final : public ui::RockMassRunner {
 public:
  std::vector<std::string> figures(const std::filesystem::path& project, storage::RecordId visit_id,
                                   const std::optional<rockmass::ClassificationForm>& save,
                                   Progress& progress) override;
};

// Trace proposals on the Mapping screen's model (issue 25):
// measure::propose_traces with the preset's knobs and the model's depth
// precision, linked to the facets found on the same model (as `rockface
// propose` does).
class FieldProposalRunner final : public ui::ProposalRunner {
 public:
  measure::ProposalResult propose(const ui::ProposalInput& input, Progress& progress,
                                  const Batch& batch) override;
};

// Issue 27: the field report from the tablet, as `rockface report` writes it.
class StoreFieldReportRunner final : public ui::FieldReportRunner {
 public:
  std::string write(const std::filesystem::path& project, storage::RecordId visit_id,
                    const std::filesystem::path& pdf, Progress& progress) override;
};

// Issue 43: the visit's exports onto a USB stick, as `rockface export`
// writes them, from its own read-only connection to the project (the sticks:
// firmware-app/services/removable_drives.h).
class StoreExportRunner final : public ui::ExportRunner {
 public:
  std::vector<ui::ExportTarget> targets() override;
  std::string write(const std::filesystem::path& project, storage::RecordId visit_id,
                    const ui::ExportTarget& target, Progress& progress) override;
};

// Issue 43: a 3D image made elsewhere as a new visit, as `rockface import`
// makes it (firmware-app/import/import_surface.h), from the tablet's storage
// or a USB stick (removable_drives.h).
class StoreImportRunner final : public ui::ImportRunner {
 public:
  std::vector<ui::ImportFolder> sticks() override;
  ui::ImportedVisit import(const std::filesystem::path& project, const std::filesystem::path& file,
                           Progress& progress) override;
};

class StoreNorthRunner final : public ui::NorthRunner {
 public:
  std::string orient(const std::filesystem::path& project, storage::RecordId visit_id,
                     const Eigen::Vector2d& from_px, const Eigen::Vector2d& to_px,
                     double bearing_deg, double declination_deg, Progress& progress) override;
};

// Issue 43: an imported cloud scaled by the pole's targets tapped on its 3D
// view (firmware-app/import/scale_import_by_pole.h).
class StorePoleRunner final : public ui::PoleRunner {
 public:
  std::string scale(const std::filesystem::path& project, storage::RecordId visit_id,
                    const Eigen::Vector3d& lower, const Eigen::Vector3d& upper, double length_m,
                    Progress& progress) override;
};

// Issue 44: the round's support on the tablet, by `rockface support`'s
// workflow (firmware-app/support/visit_support.h).
class StoreSupportRunner final : public ui::SupportRunner {
 public:
  ui::SupportProposals support(const std::filesystem::path& project, storage::RecordId visit_id,
                               const std::optional<ui::SupportChoice>& decide,
                               Progress& progress) override;
};

// source: a scene with an imaging section, a folder of captures, or empty
// (the first DSLR libgphoto2 finds).
class FieldCameraConnector final : public ui::CameraConnector {
 public:
  explicit FieldCameraConnector(std::string source) : source_(std::move(source)) {}
  std::unique_ptr<camera::Camera> connect() override;
  std::string describe() const override;

 private:
  std::string source_;
};

// Every runner of the tablet, owned in one place: what `rockface ui`
// hands the UI, and what tests that walk the real program use.
struct FieldRunners {
  explicit FieldRunners(std::string camera_source) : camera(std::move(camera_source)) {}
  StoreReconstructionRunner reconstruction;
  StoreAnalysisRunner analysis;
  FieldCameraConnector camera;
  StoreTunnelRunner tunnel;
  StoreTraceMapRunner trace_map;
  StoreWedgeRunner wedges;
  StoreSyncRunner sync;
  StoreRockMassRunner rockmass;
  FieldProposalRunner proposals;
  StoreFieldReportRunner field_report;
  StoreExportRunner exports;
  StoreNorthRunner north;
  StorePoleRunner pole;
  StoreSupportRunner support;
  StoreImportRunner imports;

  ui::FieldServices services() {
    ui::FieldServices s;
    s.reconstruction = &reconstruction;
    s.analysis = &analysis;
    s.camera = &camera;
    s.tunnel = &tunnel;
    s.trace_map = &trace_map;
    s.wedges = &wedges;
    s.sync = &sync;
    s.rockmass = &rockmass;
    s.proposals = &proposals;
    s.field_report = &field_report;
    s.exports = &exports;
    s.north = &north;
    s.pole = &pole;
    s.support = &support;
    s.imports = &imports;
    return s;
  }
};

}  // namespace rockface::app
