#pragma once

#include <QFrame>
#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

#include "fooball/run_group.h"

class QGridLayout;
class QLabel;

namespace fooball::gui {

/// The strip above the view in compare mode: a compact table of how far every run has diverged
/// from run 0 — RMS and largest position difference over balls of the same index, energy
/// difference (J and relative to run 0's) and momentum difference — one row per run k ≥ 1 with
/// its label in its run colour, and a grey row for the chaos baseline when it runs. Same scene,
/// same forces: any difference is the methods', or chaos (the baseline row says how much). The
/// header says the one moment every figure is of (the runs step on while it shows).
class CompareReadout : public QFrame {
  Q_OBJECT

 public:
  explicit CompareReadout(QWidget* parent = nullptr);

  /// All figures as plain text, one line per row ("label: RMS …, max …, energy …, momentum …"),
  /// after a first line naming run 0 and the moment ("… (run 0) at t = 4.90 s").
  QString text() const;

 public slots:
  /// The runs' labels (index = run index; [0] is the reference) and whether the baseline runs.
  /// Rebuilds the rows only when these changed, so calling it on every change is cheap. The
  /// figures read "—" until the next showDivergences().
  void showRuns(const QStringList& labels, bool baseline);
  /// Each run's divergence from run 0 and the baseline's at their moment, which the header
  /// names. A run without a figure, or the baseline without one, reads "—".
  void showDivergences(const fooball::GroupDivergences& divergences);

 private:
  /// One row of the table: a run k ≥ 1, or the baseline.
  struct Row {
    QString label;
    QLabel* name = nullptr;
    QLabel* rms = nullptr;
    QLabel* max = nullptr;
    QLabel* energy = nullptr;
    QLabel* momentum = nullptr;
  };

  /// `role` styles the row's cells ("value", or "baseline" for its grey).
  Row addRow(int gridRow, const QString& label, const QString& nameHtml, const QString& toolTip,
             const char* role);
  static void showFigures(Row& row, const std::optional<fooball::Divergence>& divergence);
  void clearRows();
  /// The header's first cell: run 0's name and, once figures are shown, their time.
  void showReference();

  QGridLayout* grid_;
  QLabel* reference_;  ///< the header's first cell: which run the differences are from
  QStringList labels_;
  std::optional<double> time_;  ///< s, of the figures shown (none before the first)
  bool baselineShown_ = false;
  bool rowsBuilt_ = false;  ///< showRuns() has run
  std::vector<Row> rows_;   ///< runs 1 … n−1, then the baseline's when shown
};

}  // namespace fooball::gui
