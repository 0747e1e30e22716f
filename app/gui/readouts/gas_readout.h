#pragma once

#include <QFrame>
#include <QString>
#include <QStringList>
#include <array>
#include <vector>

#include "fooball/gas_statistics.h"

class QGridLayout;
class QLabel;

namespace fooball::gui {

/// The statistics dock's table: a column per run (headed by its label in its run colour) with
/// the kinetic temperature, the Kolmogorov–Smirnov distance from Maxwell–Boltzmann, and the wall
/// pressure and collision rate each above what the hard-disk theory says and the ratio of the
/// two. A line above names the packing fraction and the window; where the scene is no
/// equilibrium gas in a closed box (gravity, drag, …) a warning says why and the theory's rows
/// read "n/a" rather than a ratio that means nothing.
class GasReadout : public QFrame {
  Q_OBJECT

 public:
  enum Row : int {
    kTemperature = 0,  ///< J per ball
    kDistance,         ///< KS distance, no unit
    kPressure,         ///< N/m, over the window
    kHendersonPressure,
    kPressureRatio,
    kCollisionRate,  ///< 1/s per ball, over the window
    kEnskogRate,
    kRateRatio,
    kRowCount
  };

  explicit GasReadout(QWidget* parent = nullptr);

  /// The runs' labels, run order. Rebuilds the columns only when they changed; the figures read
  /// "—" until the next showStatistics().
  void showRuns(const QStringList& labels);
  void showStatistics(const GasMonitor::Snapshot& snapshot);

  /// What the table shows in `row` for run `run`.
  QString text(Row row, int run) const;
  /// The line above the table: the packing fraction and the number of balls.
  QString summary() const;
  /// Why the theory does not apply; empty when it does.
  QString caveat() const;

 private:
  using Column = std::array<QLabel*, kRowCount>;

  QGridLayout* grid_;
  QLabel* summary_;
  QLabel* caveat_;
  std::array<QLabel*, kRowCount> captions_{};
  std::vector<QLabel*> headers_;
  std::vector<Column> columns_;
  QStringList labels_;
  bool columnsBuilt_ = false;
};

}  // namespace fooball::gui
