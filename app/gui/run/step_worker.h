#pragma once

#include <chrono>
#include <memory>

#include "fooball/simulation.h"

namespace fooball::gui {

/// A thread that runs the backend's part of one run's steps (BackendStep), so the window goes
/// on drawing and answering while a slow backend steps: Box2D can spend seconds on one step
/// when a ball is very fast. The thread stays for the next step (starting one per step cost
/// 10–20% of a 10,000-ball frame). Destroying a worker mid-step gives the step up: the backend
/// is asked to stop, and the thread finishes it, destroys it and ends by itself, so nobody waits.
class StepWorker {
 public:
  StepWorker();
  ~StepWorker();
  StepWorker(const StepWorker&) = delete;
  StepWorker& operator=(const StepWorker&) = delete;

  /// Starts `step`; the worker must be idle (no step started and not taken).
  void start(BackendStep step);
  bool busy() const { return busy_; }
  /// True once the step has finished, waiting until `deadline` at most.
  bool finishedBy(std::chrono::steady_clock::time_point deadline);
  /// The finished step, for Simulation::finishStep(); only after finishedBy() said so. Throws
  /// what the step threw.
  BackendStep take();
  /// s the step has run: so far while it runs, its whole run once it has finished (not the
  /// time until take(): the window draws while a step runs, and may take it late).
  double seconds() const;

  /// Steps given up on whose threads have not finished them yet (all workers together).
  static int givenUpStepsRunning();

 private:
  struct Shared;
  std::shared_ptr<Shared> shared_;  ///< also held by the thread until it ends
  bool busy_ = false;
};

}  // namespace fooball::gui
