#pragma once

#include <QWidget>
#include <functional>

class QLabel;
class QSlider;

namespace fooball::gui {

/// A horizontal slider on a logarithmic scale, with its value and unit shown beside it.
/// Optionally the left end is an exact zero, then the scale runs log-spaced from `minimum` to
/// `maximum` (gravity, drag and mouse strength all need "off" as well as three decades).
class LogSlider : public QWidget {
  Q_OBJECT

 public:
  struct Scale {
    double minimum = 0.01;  ///< the first non-zero value, > 0
    double maximum = 100.0;
    bool zeroAtLeft = true;
  };

  /// `formatValue` writes a value with its unit, e.g. "9.81 m/s²".
  LogSlider(Scale scale, std::function<QString(double)> formatValue, QWidget* parent = nullptr);

  double value() const { return value_; }
  QSlider* slider() const { return slider_; }

  /// Slider positions run 0..kPositions.
  static constexpr int kPositions = 600;
  double valueAt(int position) const;
  /// The position whose value is nearest to `value` on the log scale.
  int positionOf(double value) const;

 public slots:
  /// Shows `value` exactly (the handle goes to the nearest position); emits nothing.
  void setValue(double value);

 signals:
  /// The user moved the slider.
  void valueChanged(double value);

 private:
  void showValue();

  Scale scale_;
  std::function<QString(double)> formatValue_;
  QSlider* slider_;
  QLabel* valueLabel_;
  double value_ = 0.0;
};

}  // namespace fooball::gui
