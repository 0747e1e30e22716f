#include "worker_team.h"

namespace fooball::elastic {

WorkerTeam::WorkerTeam(int size) : size_(size), barrier_(size) {
  threads_.reserve(static_cast<std::size_t>(size - 1));
  for (int worker = 1; worker < size; ++worker)
    threads_.emplace_back([this, worker] { work(worker); });
}

WorkerTeam::~WorkerTeam() {
  if (size_ == 1) return;
  stopping_ = true;
  barrier_.arrive_and_wait();  // releases the workers, which see stopping_ and return
}

void WorkerTeam::runJob() {
  barrier_.arrive_and_wait();  // start: the workers read job_ after this
  call_(job_, 0);
  barrier_.arrive_and_wait();  // finish
}

void WorkerTeam::work(int worker) {
  for (;;) {
    barrier_.arrive_and_wait();
    if (stopping_) return;
    call_(job_, worker);
    barrier_.arrive_and_wait();
  }
}

}  // namespace fooball::elastic
