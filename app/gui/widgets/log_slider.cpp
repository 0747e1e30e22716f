#include "widgets/log_slider.h"

#include <QFontMetrics>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <algorithm>
#include <cmath>
#include <utility>

namespace fooball::gui {

LogSlider::LogSlider(Scale scale, std::function<QString(double)> formatValue, QWidget* parent)
    : QWidget(parent),
      scale_(scale),
      formatValue_(std::move(formatValue)),
      slider_(new QSlider(Qt::Horizontal)),
      valueLabel_(new QLabel) {
  slider_->setRange(0, kPositions);
  slider_->setPageStep(kPositions / 20);
  slider_->setSingleStep(kPositions / 100);
  valueLabel_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  valueLabel_->setMinimumWidth(QFontMetrics(valueLabel_->font()).horizontalAdvance("0.000 m/s²  "));
  setFocusProxy(slider_);

  connect(slider_, &QSlider::valueChanged, this, [this](int position) {
    value_ = valueAt(position);
    showValue();
    emit valueChanged(value_);
  });

  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(slider_, 1);
  layout->addWidget(valueLabel_);

  setValue(scale_.zeroAtLeft ? 0.0 : scale_.minimum);
}

double LogSlider::valueAt(int position) const {
  position = std::clamp(position, 0, kPositions);
  if (scale_.zeroAtLeft && position == 0) return 0.0;
  const int first = scale_.zeroAtLeft ? 1 : 0;
  const double fraction = double(position - first) / double(kPositions - first);
  return scale_.minimum * std::pow(scale_.maximum / scale_.minimum, fraction);
}

int LogSlider::positionOf(double value) const {
  if (scale_.zeroAtLeft && value <= 0.0) return 0;
  const int first = scale_.zeroAtLeft ? 1 : 0;
  const double clamped = std::clamp(value, scale_.minimum, scale_.maximum);
  const double fraction =
      std::log(clamped / scale_.minimum) / std::log(scale_.maximum / scale_.minimum);
  return first + static_cast<int>(std::lround(fraction * (kPositions - first)));
}

void LogSlider::setValue(double value) {
  value_ = value;
  const QSignalBlocker blocker(slider_);
  slider_->setValue(positionOf(value));
  showValue();
}

void LogSlider::showValue() {
  valueLabel_->setText(formatValue_(value_));
}

}  // namespace fooball::gui
