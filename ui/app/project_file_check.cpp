#include "ui/app/project_file_check.h"

#include <chrono>
#include <exception>

#include "storage/project/project_integrity.h"

namespace rockface::ui {

ProjectFileCheck::ProjectFileCheck(std::filesystem::path file) : file_(std::move(file)) {
  result_ = std::async(std::launch::async, [this] {
    try {
      return storage::check_project_file(file_, storage::IntegrityDepth::quick, &cancel_);
    } catch (const std::exception& e) {
      storage::IntegrityReport report;
      report.problems.push_back(e.what());
      return report;
    }
  });
}

ProjectFileCheck::~ProjectFileCheck() {
  cancel_ = true;
  if (result_.valid()) result_.wait();
}

bool ProjectFileCheck::running() const {
  return result_.valid() && result_.wait_for(std::chrono::seconds(0)) != std::future_status::ready;
}

void ProjectFileCheck::wait() {
  if (result_.valid()) result_.wait();
}

std::optional<std::string> ProjectFileCheck::take_problem() {
  if (taken_ || !result_.valid() || running()) return std::nullopt;
  taken_ = true;
  const storage::IntegrityReport report = result_.get();
  if (report.ok || report.problems.empty()) return std::nullopt;
  std::string text = file_.string() + ": the project file is damaged (check of the whole file: " +
                     report.problems.front() + (report.problems.size() > 1 ? ", ..." : "") +
                     "): nothing more is saved to it; copy it off the tablet as it is";
  return text;
}

}  // namespace rockface::ui
