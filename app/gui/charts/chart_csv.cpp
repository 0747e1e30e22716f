#include "chart_csv.h"

#include <QSaveFile>
#include <array>
#include <charconv>
#include <cmath>
#include <vector>

namespace fooball::gui {
namespace {

/// The CSV columns after `run` and `time`, in header order.
constexpr std::array kColumns{
    Quantity::KineticEnergy,  Quantity::PotentialEnergy,
    Quantity::TotalEnergy,    Quantity::MomentumX,
    Quantity::MomentumY,      Quantity::MomentumMagnitude,
    Quantity::EnergyResidual, Quantity::RelativeEnergyResidual,
};

void appendNumber(QByteArray& row, double value) {
  if (!std::isfinite(value)) return;
  // 32 characters hold the longest shortest form of a double ("-2.2250738585072014e-308").
  std::array<char, 32> text{};
  const auto result = std::to_chars(text.data(), text.data() + text.size(), value);
  row.append(text.data(), result.ptr - text.data());
}

/// A CSV field: quoted, with quotes doubled, when it holds a comma, quote or line break.
QByteArray csvField(const QString& text) {
  QByteArray field = text.toUtf8();
  if (field.contains(',') || field.contains('"') || field.contains('\n') || field.contains('\r')) {
    field.replace("\"", "\"\"");
    field = '"' + field + '"';
  }
  return field;
}

}  // namespace

bool writeChartCsv(const QString& path, const ChartData& data) {
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly)) return false;
  file.write(kChartCsvHeader);
  file.write("\n");

  std::vector<ChartSample> samples;
  QByteArray row;
  for (int run = 0; run < data.runCount(); ++run) {
    const QByteArray runField = csvField(data.runNames()[run]);
    data.history(run).copySince(-HUGE_VAL, samples);
    for (const ChartSample& sample : samples) {
      row = runField;
      row.append(',');
      appendNumber(row, sample.time);
      for (const Quantity quantity : kColumns) {
        row.append(',');
        appendNumber(row, sample[quantity]);
      }
      row.append('\n');
      file.write(row);
    }
  }
  return file.commit();
}

}  // namespace fooball::gui
