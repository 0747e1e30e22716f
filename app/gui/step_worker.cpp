#include "step_worker.h"

#include <atomic>
#include <condition_variable>
#include <exception>
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
  std::optional<BackendStep> step;  ///< started and not yet taken
  bool done = false;                ///< the step has run
  bool givenUp = false;             ///< the window is gone: finish the step, if any, and end
  std::exception_ptr error;         ///< what the step threw

  void serve() {
    std::unique_lock lock(mutex);
    while (true) {
      changed.wait(lock, [this] { return givenUp || (step && !done); });
      if (step && !done) {
        lock.unlock();
        std::exception_ptr thrown;
        try {
          step->run();
        } catch (...) {
          thrown = std::current_exception();  // take() throws it on the window's thread
        }
        lock.lock();
        error = thrown;
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
    shared_->done = false;
    shared_->error = nullptr;
  }
  busy_ = true;
  clock_.start();
  shared_->changed.notify_all();
}

bool StepWorker::finishedBy(std::chrono::steady_clock::time_point deadline) {
  std::unique_lock lock(shared_->mutex);
  return shared_->changed.wait_until(lock, deadline, [this] { return shared_->done; });
}

BackendStep StepWorker::take() {
  const std::lock_guard lock(shared_->mutex);
  busy_ = false;
  if (shared_->error) std::rethrow_exception(shared_->error);
  BackendStep step = std::move(*shared_->step);
  shared_->step.reset();
  return step;
}

int StepWorker::givenUpStepsRunning() {
  return givenUpSteps.load();
}

}  // namespace fooball::gui
