#include "ui/app/project_session.h"

#include <algorithm>
#include <utility>

#include "core/common/error.h"

namespace rockface::ui {

ProjectSession::ProjectSession(storage::ProjectStore store) : store_(std::move(store)) {
  info_ = store_.project();
  visits_ = store_.list_visits();
  visit_ = store_.latest_visit();
  refresh();
}

std::unique_ptr<ProjectSession> ProjectSession::open(const std::filesystem::path& file) {
  // Issue 45: the rows checked before the project opens, the photographs'
  // and 3D images' pages on a thread of their own after (the file's bulk:
  // a whole-file read of a project of 50 visits takes seconds).
  storage::OpenOptions options;
  options.check = storage::OpenOptions::Check::rows;
  auto session = std::unique_ptr<ProjectSession>(
      new ProjectSession(storage::ProjectStore::open(file, options)));
  // A project opened read-only saves nothing, and on write-protected media
  // a second connection could not share the write-ahead log's index: its
  // check would fail as if the file were damaged.
  if (!session->read_only()) session->file_check_ = std::make_unique<ProjectFileCheck>(file);
  return session;
}

std::optional<std::string> ProjectSession::take_file_problem() {
  if (!file_check_) return std::nullopt;
  auto problem = file_check_->take_problem();
  if (problem) store_.stop_writing(*problem);
  return problem;
}

std::unique_ptr<ProjectSession> ProjectSession::create(const std::filesystem::path& file,
                                                       const std::string& name) {
  storage::ProjectInfo info;
  info.name = name;
  return std::unique_ptr<ProjectSession>(
      new ProjectSession(storage::ProjectStore::create(file, info)));
}

void ProjectSession::choose_visit(storage::RecordId id) {
  visit_ = id;
  pair_ = 0;
  pairs_.clear();
  refresh();
}

void ProjectSession::choose_pair(std::size_t index) {
  if (index >= pairs_.size()) return;
  pair_ = index;
  model_ = pairs_[index];
}

storage::RecordId ProjectSession::begin_visit(const std::string& geologist) {
  const storage::RecordId id = store_.begin_visit("tablet", {}, geologist);
  visits_ = store_.list_visits();
  choose_visit(id);
  return id;
}

std::optional<std::string> ProjectSession::visit_geologist() const {
  for (const auto& v : visits_)
    if (visit_ && v.id == *visit_) return v.geologist;
  return std::nullopt;
}

void ProjectSession::name_geologist(const std::string& name) {
  if (!visit_) throw InputError("geologist", "no visit is chosen");
  store_.save_visit_geologist(*visit_, name);
  visits_ = store_.list_visits();
}

void ProjectSession::refresh() {
  visits_ = store_.list_visits();
  captures_.clear();
  measurements_.clear();
  joints_.clear();
  analysis_.reset();
  blocks_.clear();
  model_.reset();
  const std::size_t pairs_before = pairs_.size();
  pairs_.clear();
  if (visit_) {
    captures_ = store_.list_captures(*visit_);
    pairs_ = store_.list_visit_models(*visit_);
    measurements_ = store_.list_measurements(*visit_);
    joints_ = store_.list_joints(*visit_);
    const auto analyses = store_.list_analyses(*visit_);
    if (!analyses.empty()) {
      analysis_ = store_.load_analysis(analyses.back().id);
      // Each block held once (issue 37): moved into its view.
      for (auto& b : analysis_->blocks) blocks_.push_back(make_block_view(std::move(b)));
      analysis_->blocks.clear();
    }
  }
  // Models belong to captures; the visit's own (its chosen pair's) wins,
  // else the project's latest (a new visit maps on the model of an earlier
  // one).
  if (!pairs_.empty()) {
    // A pair reconstructed since (Capture) is the one to work on next.
    if (pairs_before > 0 && pairs_.size() > pairs_before) pair_ = pairs_.size() - 1;
    pair_ = std::min(pair_, pairs_.size() - 1);
    model_ = pairs_[pair_];
    return;
  }
  pair_ = 0;
  const auto models = store_.list_models();  // oldest first
  if (!models.empty()) model_ = models.back();
}

}  // namespace rockface::ui
