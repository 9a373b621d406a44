#include "firmware-app/replay/replay_refusal_undo.h"

#include <system_error>
#include <vector>

namespace rockface::app {

namespace fs = std::filesystem;

ReplayRefusalUndo::ReplayRefusalUndo(fs::path project, fs::path spool)
    : project_(std::move(project)), spool_(std::move(spool)) {
  std::error_code ec;
  project_existed_ = fs::exists(project_, ec);
  spool_existed_ = fs::is_directory(spool_, ec);
  if (!spool_existed_) return;
  for (auto it = fs::recursive_directory_iterator(spool_, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
    spool_before_.insert(it->path());
}

void ReplayRefusalUndo::remove_what_the_replay_made() const noexcept {
  std::error_code ec;
  if (!project_existed_) {
    // SQLite's side files go with the project: a WAL or journal of a
    // project that is gone would be taken by the next project of its name.
    for (const char* side : {"", "-wal", "-shm", "-journal"})
      fs::remove(project_.string() + side, ec);
  }
  if (!spool_existed_) {
    fs::remove_all(spool_, ec);
    return;
  }
  // Deepest first, so that a folder the replay made is empty when reached.
  std::vector<fs::path> added;
  for (auto it = fs::recursive_directory_iterator(spool_, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
    if (!spool_before_.count(it->path())) added.push_back(it->path());
  for (auto p = added.rbegin(); p != added.rend(); ++p) fs::remove_all(*p, ec);
}

std::string ReplayRefusalUndo::said(const std::string& reason) const {
  return reason + "; the replay stored nothing: " +
         (project_existed_ ? "the project is as it was" : "no project was made");
}

}  // namespace rockface::app
