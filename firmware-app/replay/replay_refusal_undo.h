#pragma once
// What a refused replay must not leave behind (issue 41): a replay refused
// after its project was opened (a face off the alignment, a placement that
// fails, picks the analysis refuses) left a new project with its first visit
// half stored, and a visit in an existing one. The replay's saves run in one
// transaction (an existing project's bytes stay as they were); this removes
// what the replay made outside it: a project file it created, with its
// SQLite side files, and the photographs it spooled.
#include <filesystem>
#include <set>
#include <string>

namespace rockface::app {

class ReplayRefusalUndo {
 public:
  // Notes what exists before the replay writes anything: the project file
  // and the spool folder's files.
  ReplayRefusalUndo(std::filesystem::path project, std::filesystem::path spool);

  // After a refusal (the project's store closed): removes the project when
  // the replay created it, and every file and folder of the spool the
  // replay added. Never throws (it runs while an error propagates).
  void remove_what_the_replay_made() const noexcept;

  // The refusal's reason with what it left: "; the replay stored nothing:
  // the project is as it was" (or "no project was made").
  std::string said(const std::string& reason) const;

 private:
  std::filesystem::path project_, spool_;
  bool project_existed_ = false, spool_existed_ = false;
  std::set<std::filesystem::path> spool_before_;
};

}  // namespace rockface::app
