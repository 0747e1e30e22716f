#include "metrics_csv.h"

#include "fooball/number_text.h"

namespace fooball::cli {

MetricsCsv::MetricsCsv(const std::filesystem::path& path) : file_(path, "--metrics", kHeader) {}

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
  file_.write(row_);
}

void MetricsCsv::close() {
  file_.close();
}

}  // namespace fooball::cli
