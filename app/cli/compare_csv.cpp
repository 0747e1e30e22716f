#include "compare_csv.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "fooball/number_text.h"
#include "usage_error.h"

namespace fooball::cli {

namespace {

/// A spec with several options has commas ("box2d:substeps=8,velocity_iterations=20"): such a
/// field is quoted as RFC 4180 says, so every row keeps its nine columns.
void appendField(std::string& row, std::string_view text) {
  if (text.find_first_of(",\"\n") == std::string_view::npos) {
    row += text;
    return;
  }
  row += '"';
  for (const char c : text) {
    if (c == '"') row += '"';
    row += c;
  }
  row += '"';
}

}  // namespace

CompareCsv::CompareCsv(const std::filesystem::path& path)
    : path_(path), file_(std::fopen(path.c_str(), "w")) {
  if (!file_) {
    throw UsageError("--csv '" + path.string() +
                     "': cannot open for writing: " + std::strerror(errno));
  }
  std::fputs(kHeader, file_.get());
  std::fputc('\n', file_.get());
}

void CompareCsv::writeRow(std::string_view run, const Metrics& metrics,
                          const Divergence& fromReference) {
  row_.clear();
  const auto addNumber = [this](double value) {
    row_ += ',';
    row_ += exactNumberText(value);
  };
  row_ += exactNumberText(metrics.time);
  row_ += ',';
  appendField(row_, run);
  addNumber(metrics.sums.kineticEnergy);
  addNumber(metrics.sums.totalEnergy());
  addNumber(metrics.sums.momentum.x);
  addNumber(metrics.sums.momentum.y);
  addNumber(metrics.energyResidual);
  addNumber(fromReference.rmsPositionDifference);
  addNumber(fromReference.maxPositionDifference);
  row_ += '\n';
  std::fwrite(row_.data(), 1, row_.size(), file_.get());
}

void CompareCsv::close() {
  const bool writeFailed = std::ferror(file_.get()) != 0;
  // fclose flushes the buffer, so it can be the first call to see a full disk.
  const bool closeFailed = std::fclose(file_.release()) != 0;
  if (writeFailed || closeFailed) {
    throw std::runtime_error("--csv '" + path_.string() +
                             "': writing failed: " + std::strerror(errno));
  }
}

}  // namespace fooball::cli
