#pragma once

#include <QGroupBox>
#include <QStringList>
#include <cstdint>
#include <vector>

#include "fooball/metrics.h"

class QGridLayout;
class QLabel;

namespace fooball::gui {

/// The sidebar's "Counters" table: per run (its spec in its colour on a line of its own, never
/// cut short) the ball–ball collisions and wall
/// bounces since the scene was loaded, the deepest overlap now (ball–ball or ball–wall, as a
/// fraction of the smaller radius) and the balls whose centre is outside the box — what
/// `fooball-cli run` reports, for every run of the group. Its width does not grow with the
/// counts up to 100 million collisions. A run whose backend holds balls at rest (exact's
/// ball_rest_time) says how many beside its name, as `fooball-cli run` does.
class RunCounters : public QGroupBox {
  Q_OBJECT

 public:
  explicit RunCounters(QWidget* parent = nullptr);

  /// The runs' labels, run 0 first; rebuilds the rows only when they changed. The figures read
  /// "—" until the next showMetrics().
  void showRuns(const QStringList& labels);
  /// Each run's metrics (index = run index).
  void showMetrics(const std::vector<Metrics>& metrics);

  /// The table as plain text, one line per run: "label: 2515 ball–ball, 503 wall, overlap 0.3 %,
  /// 0 escaped", and ", 624 resting" while the backend holds balls at rest.
  QString text() const;

 private:
  struct Row {
    QString label;
    QString nameHtml;  ///< the coloured dot and the spec
    std::uint64_t resting = 0;
    QLabel* name = nullptr;
    QLabel* ballCollisions = nullptr;
    QLabel* wallCollisions = nullptr;
    QLabel* overlap = nullptr;
    QLabel* escaped = nullptr;
  };

  QGridLayout* grid_;
  QStringList labels_;
  std::vector<Row> rows_;
};

}  // namespace fooball::gui
