#pragma once

#include <QPointF>
#include <QString>
#include <QWidget>
#include <cstddef>
#include <vector>

class QChart;
class QChartView;
class QLabel;
class QXYSeries;

namespace fooball::gui {

/// The charts of a Tools dialog, side by side under one heading, in the app's dark theme: the
/// ones fooball-cli draws (app/shared/plots), whose points stand for measurements
/// (plots/measured_points.h). Clicking a point says which measurement it stands for.
class MeasuredCharts : public QWidget {
  Q_OBJECT

 public:
  /// `placeholder`: what shows until there are charts, e.g. what will appear after Start.
  explicit MeasuredCharts(const QString& placeholder, QWidget* parent = nullptr);

  /// Shows `charts` (taken over) under `title`; none: the placeholder again.
  void showCharts(std::vector<QChart*> charts, const QString& title);
  /// What shows while there are no charts (while a run goes, that it is measuring).
  void setPlaceholder(const QString& placeholder);
  QString placeholder() const;
  /// The charts shown, left to right.
  const std::vector<QChartView*>& views() const { return views_; }

  /// What a click on `series` at `value` (in the axes' values) does: the measurement of the
  /// nearest point, if the series has measurements.
  void pointClicked(QXYSeries* series, QPointF value);

 signals:
  /// The point of measurement `index` (into the measurements the charts were made from) was
  /// clicked.
  void measurementClicked(std::size_t index);

 private:
  QLabel* title_;
  QLabel* placeholder_;
  QWidget* row_;
  std::vector<QChartView*> views_;
};

}  // namespace fooball::gui
