#include "chart_csv.h"

#include <QSaveFile>
#include <array>
#include <cmath>
#include <vector>

#include "fooball/number_text.h"

namespace fooball::gui {
namespace {

/// The CSV columns after `run` and `time`, in header order.
constexpr std::array kColumns{
    Quantity::KineticEnergy,
    Quantity::PotentialEnergy,
    Quantity::TotalEnergy,
    Quantity::MomentumX,
    Quantity::MomentumY,
    Quantity::MomentumMagnitude,
    Quantity::EnergyResidual,
    Quantity::RelativeEnergyResidual,
    Quantity::RmsPositionDifference,
    Quantity::MaxPositionDifference,
};

void appendNumber(QByteArray& row, double value) {
  if (!std::isfinite(value)) return;
  row.append(exactNumberText(value));
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
  const auto writeRun = [&](const QByteArray& runField, const SampleHistory& history) {
    history.copySince(-HUGE_VAL, samples);
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
  };
  for (int run = 0; run < data.runCount(); ++run)
    writeRun(csvField(data.runName(run)), data.history(run));
  if (data.baselineShown()) writeRun(kBaselineCsvRun, data.history(ChartData::kBaseline));
  return file.commit();
}

}  // namespace fooball::gui
