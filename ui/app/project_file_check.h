#pragma once
// The whole-file check of a project the tablet opened with a check of its
// rows only (storage/project/project_integrity.h): opening a project of
// many visits must not wait for a read of every photograph and 3D image
// (issue 45: a project of 50 visits opens in under a second), so those
// pages are read on a thread of their own, on a read-only connection of its
// own, while the geologist works. A damaged file found there stops the
// session's saves (the store goes read-only) and says what and where.
#include <atomic>
#include <filesystem>
#include <future>
#include <optional>
#include <string>

#include "storage/project/project_records.h"

namespace rockface::ui {

class ProjectFileCheck {
 public:
  explicit ProjectFileCheck(std::filesystem::path file);
  // Stops the check (an SQLite progress handler) and waits for it.
  ~ProjectFileCheck();
  ProjectFileCheck(const ProjectFileCheck&) = delete;
  ProjectFileCheck& operator=(const ProjectFileCheck&) = delete;

  bool running() const;
  // Once, when the check has ended and found the file damaged (or could
  // not read it): the problem in words, naming the file.
  std::optional<std::string> take_problem();
  // Waits for the end (tests, and a script's "wait").
  void wait();

 private:
  std::filesystem::path file_;
  std::atomic<bool> cancel_{false};
  std::future<storage::IntegrityReport> result_;
  bool taken_ = false;
};

}  // namespace rockface::ui
