#include "compare_csv.h"

#include "fooball/number_text.h"

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

CompareCsv::CompareCsv(const std::filesystem::path& path) : file_(path, "--csv", kHeader) {}

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
  file_.write(row_);
}

void CompareCsv::close() {
  file_.close();
}

}  // namespace fooball::cli
