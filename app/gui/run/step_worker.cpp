#include "run/step_worker.h"

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace fooball::gui {

namespace {

std::atomic<int> givenUpSteps = 0;

}  // namespace

/// What the window's thread and the worker's thread share, under `mutex`.
struct StepWorker::Shared {
  std::mutex mutex;
  std::condition_variable changed;
  std::optional<BackendStep> step;                ///< started and not yet taken
  std::chrono::steady_clock::time_point started;  ///< handed over, then begun on the thread
  std::chrono::steady_clock::duration ran{};      ///< how long the step ran, once done
  bool done = false;                              ///< the step has run
  bool givenUp = false;  ///< the window is gone: finish the step, if any, and end

  void serve() {
    std::unique_lock lock(mutex);
    while (true) {
      changed.wait(lock, [this] { return givenUp || (step && !done); });
      if (step && !done) {
        // The step's cost starts here, not at start(): waking this thread is none of it.
        started = std::chrono::steady_clock::now();
        lock.unlock();
        step->run();  // a failure stays in the step (BackendStep::failure)
        lock.lock();
        ran = std::chrono::steady_clock::now() - started;
        done = true;
        changed.notify_all();
        if (givenUp) --givenUpSteps;
      }
      if (givenUp) return;
    }
  }
};

StepWorker::StepWorker() : shared_(std::make_shared<Shared>()) {
  std::thread([shared = shared_] { shared->serve(); }).detach();
}

StepWorker::~StepWorker() {
  const std::lock_guard lock(shared_->mutex);
  shared_->givenUp = true;
  if (busy_ && !shared_->done) {
    shared_->step->backend().requestStop();
    ++givenUpSteps;
  }
  shared_->changed.notify_all();
}

void StepWorker::start(BackendStep step) {
  {
    const std::lock_guard lock(shared_->mutex);
    shared_->step = std::move(step);
    shared_->started = std::chrono::steady_clock::now();
    shared_->done = false;
  }
  busy_ = true;
  shared_->changed.notify_all();
}

bool StepWorker::finishedBy(std::chrono::steady_clock::time_point deadline) {
  std::unique_lock lock(shared_->mutex);
  return shared_->changed.wait_until(lock, deadline, [this] { return shared_->done; });
}

BackendStep StepWorker::take() {
  const std::lock_guard lock(shared_->mutex);
  busy_ = false;
  BackendStep step = std::move(*shared_->step);
  shared_->step.reset();
  return step;
}

double StepWorker::seconds() const {
  const std::lock_guard lock(shared_->mutex);
  const auto ran =
      shared_->done ? shared_->ran : std::chrono::steady_clock::now() - shared_->started;
  return std::chrono::duration<double>(ran).count();
}

int StepWorker::givenUpStepsRunning() {
  return givenUpSteps.load();
}

}  // namespace fooball::gui
