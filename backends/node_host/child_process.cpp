#include "child_process.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "fooball/number_text.h"

extern char** environ;

namespace fooball::node_host {

namespace {

void closeFd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

void setNonBlocking(int fd) {
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
}

/// Blocks SIGPIPE in this thread while alive, so that a write to a pipe whose reader has gone
/// fails with EPIPE instead of killing the program; a SIGPIPE raised meanwhile is taken back.
class SigpipeBlock {
 public:
  SigpipeBlock() {
    sigset_t pipe;
    sigemptyset(&pipe);
    sigaddset(&pipe, SIGPIPE);
    sigset_t pending;
    sigpending(&pending);
    wasPending_ = sigismember(&pending, SIGPIPE) == 1;
    pthread_sigmask(SIG_BLOCK, &pipe, &old_);
  }
  ~SigpipeBlock() {
    if (!wasPending_) {
      sigset_t pipe;
      sigemptyset(&pipe);
      sigaddset(&pipe, SIGPIPE);
      const timespec now{0, 0};
      while (sigtimedwait(&pipe, nullptr, &now) == SIGPIPE) {
      }
    }
    pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }
  SigpipeBlock(const SigpipeBlock&) = delete;
  SigpipeBlock& operator=(const SigpipeBlock&) = delete;

 private:
  sigset_t old_;
  bool wasPending_ = false;
};

int millisecondsUntil(ChildProcess::Clock::time_point deadline) {
  const auto left =
      std::chrono::ceil<std::chrono::milliseconds>(deadline - ChildProcess::Clock::now());
  return static_cast<int>(std::clamp<std::chrono::milliseconds::rep>(left.count(), 0, 60'000));
}

}  // namespace

ChildProcess::ChildProcess(const std::vector<std::string>& argv) {
  int in[2], out[2], err[2];
  if (::pipe2(in, O_CLOEXEC) != 0)
    throw std::runtime_error("pipe: " + std::string(strerror(errno)));
  if (::pipe2(out, O_CLOEXEC) != 0) {
    ::close(in[0]);
    ::close(in[1]);
    throw std::runtime_error("pipe: " + std::string(strerror(errno)));
  }
  if (::pipe2(err, O_CLOEXEC) != 0) {
    for (int fd : {in[0], in[1], out[0], out[1]})
      ::close(fd);
    throw std::runtime_error("pipe: " + std::string(strerror(errno)));
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, err[1], STDERR_FILENO);
  // The child starts with no signal blocked and default SIGPIPE, whatever this thread has.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t none, pipe;
  sigemptyset(&none);
  sigemptyset(&pipe);
  sigaddset(&pipe, SIGPIPE);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setsigdefault(&attributes, &pipe);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);

  std::vector<char*> args;
  for (const std::string& arg : argv)
    args.push_back(const_cast<char*>(arg.c_str()));
  args.push_back(nullptr);
  const int spawned = posix_spawnp(&pid_, args[0], &actions, &attributes, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(in[0]);
  ::close(out[1]);
  ::close(err[1]);
  stdin_ = in[1];
  stdout_ = out[0];
  stderr_fd_ = err[0];
  if (spawned != 0) {
    pid_ = -1;
    closeFd(stdin_);
    closeFd(stdout_);
    closeFd(stderr_fd_);
    throw std::runtime_error("cannot start '" + argv[0] + "': " + strerror(spawned));
  }
  setNonBlocking(stdin_);
  setNonBlocking(stdout_);
  setNonBlocking(stderr_fd_);
}

ChildProcess::~ChildProcess() {
  killAndReap();
  closeFd(stdin_);
  closeFd(stdout_);
  closeFd(stderr_fd_);
}

void ChildProcess::killAndReap() {
  if (pid_ < 0 || reaped_) return;
  ::kill(pid_, SIGKILL);
  while (::waitpid(pid_, &waitStatus_, 0) < 0 && errno == EINTR) {
  }
  reaped_ = true;
}

void ChildProcess::drainStderr() {
  if (stderr_fd_ < 0) return;
  char chunk[4096];
  for (;;) {
    const ssize_t n = ::read(stderr_fd_, chunk, sizeof chunk);
    if (n > 0) {
      stderr_.append({chunk, static_cast<std::size_t>(n)});
      continue;
    }
    if (n == 0) closeFd(stderr_fd_);  // the child closed it: it is ending
    return;
  }
}

bool ChildProcess::waitFor(int fd, short events, Clock::time_point deadline) {
  for (;;) {
    pollfd fds[2] = {{fd, events, 0}, {stderr_fd_, POLLIN, 0}};
    const int count = stderr_fd_ >= 0 ? 2 : 1;
    const int ready = ::poll(fds, count, millisecondsUntil(deadline));
    if (ready < 0 && errno == EINTR) continue;
    if (count == 2 && fds[1].revents != 0) drainStderr();
    if (fds[0].revents != 0) return true;  // ready, or closed: the read or write will say
    if (Clock::now() >= deadline) {
      fault_ = ChildFault::Hung;
      return false;
    }
  }
}

bool ChildProcess::write(std::span<const std::byte> bytes, Clock::time_point deadline) {
  if (fault_ != ChildFault::None) return false;
  const SigpipeBlock block;
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(stdin_, bytes.data() + done, bytes.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EAGAIN) {
      if (!waitFor(stdin_, POLLOUT, deadline)) return false;
      continue;
    }
    fault_ = ChildFault::Exited;  // EPIPE: nobody reads any more
    return false;
  }
  return true;
}

bool ChildProcess::read(std::span<std::byte> bytes, Clock::time_point deadline) {
  if (fault_ != ChildFault::None) return false;
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::read(stdout_, bytes.data() + done, bytes.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EAGAIN) {
      if (!waitFor(stdout_, POLLIN, deadline)) return false;
      continue;
    }
    fault_ = ChildFault::Exited;  // end of file: the child has closed its stdout
    return false;
  }
  return true;
}

std::string ChildProcess::failure(std::chrono::milliseconds timeout) {
  std::string why;
  switch (fault_) {
    case ChildFault::Hung:
      why = "did not answer within " +
            exactNumberText(std::chrono::duration<double>(timeout).count()) +
            " s, so it was killed";
      break;
    case ChildFault::Garbage:
      why = "answered something that is not the host protocol, so it was killed";
      break;
    case ChildFault::Exited:
    case ChildFault::None: {
      // Give a child that is ending a moment to finish, so that its status is its own.
      for (int wait = 0; wait < 50 && !reaped_; ++wait) {
        const pid_t done = ::waitpid(pid_, &waitStatus_, WNOHANG);
        if (done == pid_) {
          reaped_ = true;
          break;
        }
        ::usleep(10'000);
      }
      if (!reaped_) why = "stopped answering, so it was killed";
      break;
    }
  }
  const bool endedOnItsOwn = reaped_ && why.empty();
  killAndReap();
  drainStderr();
  if (endedOnItsOwn) {
    if (WIFEXITED(waitStatus_)) {
      why = "exited with status " + std::to_string(WEXITSTATUS(waitStatus_));
    } else if (WIFSIGNALED(waitStatus_)) {
      why = "was killed by signal " + std::to_string(WTERMSIG(waitStatus_)) + " (" +
            strsignal(WTERMSIG(waitStatus_)) + ")";
    }
  }
  return why;
}

}  // namespace fooball::node_host
