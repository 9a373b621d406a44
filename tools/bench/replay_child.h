#pragma once
// `rockface replay` run as a child process, each of its progress lines
// (core/common/progress.h, "replay: STAGE" on stderr) timestamped on arrival
// with the child's CPU time and peak resident set so far. Shared by the
// benchmarks that time the field workflow stage by stage
// (face_to_verdicts_bench.cpp, visit_bench.cpp): benches do not link the
// workflow's binary, and the child's own peak is the figure a tablet meets.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace rockface::bench {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Peak resident set so far of process `pid`, MB (0 when unreadable).
inline double vm_hwm_mb(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kB
  return 0;
}

// CPU time of process `pid` so far, all its threads (utime + stime of
// /proc/PID/stat, fields 14 and 15), seconds; 0 when unreadable. The figure
// a loaded machine leaves closest to the work's own cost.
inline double process_cpu_s(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // The command name (field 2) is in parentheses and may hold spaces.
  const auto close = text.rfind(')');
  if (close == std::string::npos) return 0;
  std::istringstream fields(text.substr(close + 2));
  std::string f;
  long long utime = 0, stime = 0;
  for (int i = 3; i <= 15 && fields >> f; ++i) {
    if (i == 14) utime = std::stoll(f);
    if (i == 15) stime = std::stoll(f);
  }
  return static_cast<double>(utime + stime) / static_cast<double>(::sysconf(_SC_CLK_TCK));
}

struct StageMark {
  std::string stage;  // the progress line after "replay: "
  double at_s = 0;    // wall, since the child started
  double cpu_s = 0;   // the child's CPU time so far
  double hwm_mb = 0;  // the child's peak resident set so far
};

struct ReplayRun {
  std::vector<StageMark> marks;
  double total_s = 0, cpu_s = 0, peak_mb = 0;
  int status = -1;
  bool ok() const { return WIFEXITED(status) && WEXITSTATUS(status) == 0; }
};

// `ROCKFACE_BINARY_DIR/rockface replay SCENE --project PROJECT --preset P`.
inline ReplayRun run_replay(const std::string& binary, const std::string& scene,
                            const std::string& project, const std::string& preset) {
  ReplayRun run;
  int fds[2];
  if (::pipe(fds) != 0) return run;
  const auto t0 = Clock::now();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return run;
  }
  if (pid == 0) {
    ::dup2(fds[1], 2);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    ::close(fds[0]);
    ::close(fds[1]);
    ::execl(binary.c_str(), binary.c_str(), "replay", scene.c_str(), "--project", project.c_str(),
            "--preset", preset.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(fds[1]);
  FILE* err = ::fdopen(fds[0], "r");
  char buf[512];
  while (std::fgets(buf, sizeof buf, err)) {
    std::string line(buf);
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
    const std::string prefix = "replay: ";
    if (line.rfind(prefix, 0) == 0)
      run.marks.push_back(
          {line.substr(prefix.size()), seconds_since(t0), process_cpu_s(pid), vm_hwm_mb(pid)});
  }
  std::fclose(err);
  rusage u{};
  ::wait4(pid, &run.status, 0, &u);
  run.total_s = seconds_since(t0);
  run.cpu_s = static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
              1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  run.peak_mb = u.ru_maxrss / 1024.0;  // kB on Linux
  return run;
}

}  // namespace rockface::bench
