#pragma once
// A test-only SQLite VFS that wraps the default one and turns write, sync or
// truncate calls into I/O errors from a chosen call on, or kills the process
// at a chosen call, — a storage card that
// starts failing in the middle of a save. This is SQLite's own way of testing
// I/O-error handling (its test suite injects faults through a VFS too); the
// code under test runs unchanged on top of it.
#include <string>

namespace rockface::storage::test {

class FaultyVfs {
 public:
  static constexpr const char* kName = "rockface-faulty";
  // Registers the VFS once (not as the default).
  static void install();
  // From the n-th write/sync/truncate call on (1-based), every such call
  // fails with SQLITE_IOERR_*; 0 disarms. Counting restarts at arm().
  static void arm(int fail_from_call);
  static void disarm() { arm(0); }
  // A flat battery at a chosen moment: the process kills itself with SIGKILL
  // right before its n-th write/sync/truncate call (1-based) from now on;
  // 0 disarms. For a child process of a crash test.
  static void arm_kill(int at_call);
  // write/sync/truncate calls since the last arm() or arm_kill().
  static int calls();
};

}  // namespace rockface::storage::test
