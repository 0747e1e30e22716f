#pragma once

#include <barrier>
#include <thread>
#include <vector>

namespace fooball::elastic {

/// A fixed team of threads that runs one job at a time. The calling thread is worker 0, so a
/// team of one has no threads of its own. The threads start once, sleep between jobs, and are
/// handed each job by pointer: nothing is created or allocated per job.
class WorkerTeam {
 public:
  explicit WorkerTeam(int size);
  ~WorkerTeam();
  WorkerTeam(const WorkerTeam&) = delete;
  WorkerTeam& operator=(const WorkerTeam&) = delete;

  int size() const { return size_; }

  /// Calls job(worker) on every worker, worker = 0 … size()−1, and returns when all are done.
  template <class Job>
  void run(Job& job) {
    if (size_ == 1) {
      job(0);
      return;
    }
    job_ = &job;
    call_ = [](void* context, int worker) { (*static_cast<Job*>(context))(worker); };
    runJob();
  }

  /// Inside a job: returns once every worker has reached the same sync().
  void sync() {
    if (size_ > 1) barrier_.arrive_and_wait();
  }

 private:
  void runJob();
  void work(int worker);

  int size_;
  std::barrier<> barrier_;
  void* job_ = nullptr;
  void (*call_)(void*, int) = nullptr;
  bool stopping_ = false;
  std::vector<std::jthread> threads_;
};

}  // namespace fooball::elastic
