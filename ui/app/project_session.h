#pragma once
// The project open on the UI thread: its store (the UI thread's own SQLite
// connection), the visit being worked on, and what that visit holds, read
// again after every step a worker saved (refresh()).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "storage/project/project_store.h"
#include "ui/app/project_file_check.h"
#include "ui/blocks/block_view.h"

namespace rockface::ui {

class ProjectSession {
 public:
  // Opens an existing project (read-only when the store says so) or
  // creates a new one; throws rockface::Error / InputError naming the file.
  static std::unique_ptr<ProjectSession> open(const std::filesystem::path& file);
  static std::unique_ptr<ProjectSession> create(const std::filesystem::path& file,
                                                const std::string& name);

  storage::ProjectStore& store() { return store_; }
  const std::filesystem::path& file() const { return store_.file(); }
  bool read_only() const { return store_.read_only(); }
  // The whole file's check after an opening (ui/app/project_file_check.h):
  // once, when it found the file damaged, the problem (the store has then
  // stopped saving); nothing while it runs or when the file is sound.
  std::optional<std::string> take_file_problem();
  bool checking_file() const { return file_check_ && file_check_->running(); }
  void wait_for_file_check() {
    if (file_check_) file_check_->wait();
  }
  const std::string& read_only_reason() const { return store_.read_only_reason(); }
  const storage::ProjectInfo& info() const { return info_; }

  const std::vector<storage::Visit>& visits() const { return visits_; }
  std::optional<storage::RecordId> visit() const { return visit_; }
  void choose_visit(storage::RecordId id);
  // Starts a visit from the tablet (the project must be writable), mapped
  // by `geologist` ("" none: storage/project/visit_geologist.h).
  storage::RecordId begin_visit(const std::string& geologist = {});
  // The chosen visit's geologist; none when not recorded (or no visit).
  std::optional<std::string> visit_geologist() const;
  // Names the chosen visit's geologist ("" takes the name away); InputError
  // for a name the store refuses, nothing stored then.
  void name_geologist(const std::string& name);

  // Re-reads the lists of the current visit.
  void refresh();

  const std::vector<storage::CaptureSummary>& captures() const { return captures_; }
  // The visit's 3D images, one per stereo pair (ProjectStore::list_visit_models):
  // all in the face frame, the first pair's.
  const std::vector<storage::ModelSummary>& pairs() const { return pairs_; }
  // The pair worked on (0-based); the first when the visit is chosen.
  std::size_t pair() const { return pair_; }
  void choose_pair(std::size_t index);
  // The model to work on: the chosen pair's of the visit, else the
  // project's latest (a new visit maps on the model of an earlier one).
  const std::optional<storage::ModelSummary>& model() const { return model_; }
  const std::vector<storage::Measurement>& measurements() const { return measurements_; }
  const std::vector<storage::Joint>& joints() const { return joints_; }
  // The visit's latest analysis; its blocks are in blocks(), each with its
  // verdict in words (held once: the run's own list is left empty).
  const std::optional<storage::AnalysisRun>& analysis() const { return analysis_; }
  const std::vector<BlockView>& blocks() const { return blocks_; }

 private:
  explicit ProjectSession(storage::ProjectStore store);
  storage::ProjectStore store_;
  std::unique_ptr<ProjectFileCheck> file_check_;
  storage::ProjectInfo info_;
  std::vector<storage::Visit> visits_;
  std::optional<storage::RecordId> visit_;
  std::vector<storage::CaptureSummary> captures_;
  std::vector<storage::ModelSummary> pairs_;
  std::size_t pair_ = 0;
  std::optional<storage::ModelSummary> model_;
  std::vector<storage::Measurement> measurements_;
  std::vector<storage::Joint> joints_;
  std::optional<storage::AnalysisRun> analysis_;
  std::vector<BlockView> blocks_;
};

}  // namespace rockface::ui
