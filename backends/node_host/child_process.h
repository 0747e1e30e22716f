#pragma once

#include <sys/types.h>

#include <chrono>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "stderr_tail.h"

namespace fooball::node_host {

/// Why the child stopped talking; ChildProcess::failure() says it in words.
enum class ChildFault {
  None,
  Exited,   ///< closed its stdout or stdin: it ended, or is ending
  Hung,     ///< no answer before the deadline
  Garbage,  ///< answered something the protocol does not allow (set by the caller)
};

/// One child process with its stdin and stdout as pipes to us and its stderr kept in a StderrTail.
/// posix_spawnp, so the program is found on PATH as a shell would. Reads and writes take a
/// deadline and drain the child's stderr while they wait (a child blocked on a full stderr pipe
/// never reads its stdin). A write to a child that has gone reports Exited, never SIGPIPE. The
/// destructor kills the child (SIGKILL) and reaps it: no zombie is left, whatever happened.
class ChildProcess {
 public:
  using Clock = std::chrono::steady_clock;

  /// Starts argv[0] with `argv`. Throws std::runtime_error naming the program if it cannot start.
  explicit ChildProcess(const std::vector<std::string>& argv);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  /// Writes all of `bytes` to the child's stdin; false (and fault() set) if it could not.
  bool write(std::span<const std::byte> bytes, Clock::time_point deadline);
  /// Reads exactly bytes.size() bytes from its stdout; false (and fault() set) if it could not.
  bool read(std::span<std::byte> bytes, Clock::time_point deadline);

  /// Marks the child as having answered garbage (the protocol's judgement).
  void markGarbage() { fault_ = ChildFault::Garbage; }
  ChildFault fault() const { return fault_; }

  /// Kills and reaps the child if it still runs, then says how it ended and why we gave up on it,
  /// e.g. "exited with status 1" or "was killed by signal 9" or "did not answer within 30 s".
  std::string failure(std::chrono::milliseconds timeout);
  /// What the child has written to its stderr lately.
  std::string stderrTail() {
    drainStderr();
    return stderr_.text();
  }

  pid_t pid() const { return pid_; }

 private:
  /// Waits until `fd` is ready for `events` or the deadline passes, draining stderr meanwhile.
  /// Returns false on a hang or a closed pipe (fault_ set).
  bool waitFor(int fd, short events, Clock::time_point deadline);
  void drainStderr();
  /// SIGKILL and waitpid, once; keeps the wait status.
  void killAndReap();

  pid_t pid_ = -1;
  int stdin_ = -1;   ///< our end: we write
  int stdout_ = -1;  ///< our end: we read
  int stderr_fd_ = -1;
  StderrTail stderr_;
  ChildFault fault_ = ChildFault::None;
  bool reaped_ = false;
  int waitStatus_ = 0;
};

}  // namespace fooball::node_host
