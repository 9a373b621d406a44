// A test binary that dies of a signal (a segfault in CI only, under load)
// says which test and which thread died and where, before it dies as it
// would have: CI keeps no core file, and a suite run as one process
// (ONE_PROCESS) otherwise names only its binary. Linked into every test
// (tests/CMakeLists.txt); left out under AddressSanitizer, whose own report
// is better.
#include <execinfo.h>
#include <signal.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>

#include <gtest/gtest.h>

namespace {

#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)

void write_text(const char* text) {
  const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
  (void)ignored;
}

void on_fatal_signal(int sig) {
  // The test's name is read from GoogleTest's state: not async-signal-safe,
  // but the process is dying anyway and the name is what a CI log needs.
  char line[512];
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  std::snprintf(line, sizeof line, "\n*** %s in test %s.%s, thread %ld (main %ld); stack:\n",
                strsignal(sig), test ? test->test_suite_name() : "(none)",
                test ? test->name() : "(none)", static_cast<long>(::syscall(SYS_gettid)),
                static_cast<long>(::getpid()));
  write_text(line);
  void* frames[64];
  const int n = ::backtrace(frames, 64);
  ::backtrace_symbols_fd(frames, n, STDERR_FILENO);
  // Die of the same signal, so that CTest reports it as before.
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

[[maybe_unused]] const bool installed = [] {
  // backtrace() loads libgcc on its first call: done here, not in the handler.
  void* warm[1];
  ::backtrace(warm, 1);
  for (const int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) ::signal(sig, on_fatal_signal);
  return true;
}();

#endif

}  // namespace
