#include "metrics_csv.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "fooball/number_text.h"
#include "usage_error.h"

namespace fooball::cli {

MetricsCsv::MetricsCsv(const std::filesystem::path& path)
    : path_(path), file_(std::fopen(path.c_str(), "w")) {
  if (!file_) {
    throw UsageError("--metrics '" + path.string() +
                     "': cannot open for writing: " + std::strerror(errno));
  }
  std::fputs(kHeader, file_.get());
  std::fputc('\n', file_.get());
}

void MetricsCsv::writeRow(const Metrics& metrics) {
  row_.clear();
  const auto addNumber = [this](double value) {
    row_ += exactNumberText(value);
    row_ += ',';
  };
  addNumber(metrics.time);
  addNumber(metrics.sums.kineticEnergy);
  addNumber(metrics.sums.potentialEnergy);
  addNumber(metrics.sums.totalEnergy());
  addNumber(metrics.sums.momentum.x);
  addNumber(metrics.sums.momentum.y);
  row_ += std::to_string(metrics.ballCollisions) + ',';
  row_ += std::to_string(metrics.wallCollisions) + ',';
  addNumber(metrics.wallImpulse);
  addNumber(metrics.maxOverlap);
  row_ += std::to_string(metrics.escaped) + '\n';
  std::fwrite(row_.data(), 1, row_.size(), file_.get());
}

void MetricsCsv::close() {
  const bool writeFailed = std::ferror(file_.get()) != 0;
  // fclose flushes the buffer, so it can be the first call to see a full disk.
  const bool closeFailed = std::fclose(file_.release()) != 0;
  if (writeFailed || closeFailed) {
    throw std::runtime_error("--metrics '" + path_.string() +
                             "': writing failed: " + std::strerror(errno));
  }
}

}  // namespace fooball::cli
