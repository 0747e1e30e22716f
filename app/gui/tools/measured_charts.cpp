#include "tools/measured_charts.h"

#include <QChart>
#include <QChartView>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <QXYSeries>

#include "measured_points.h"
#include "widgets/dark_theme.h"

namespace fooball::gui {

MeasuredCharts::MeasuredCharts(const QString& placeholder, QWidget* parent) : QWidget(parent) {
  title_ = new QLabel;
  title_->setWordWrap(true);
  title_->setAlignment(Qt::AlignHCenter);
  title_->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Maximum);  // the charts get the rest
  placeholder_ = new QLabel(placeholder);
  placeholder_->setWordWrap(true);
  placeholder_->setAlignment(Qt::AlignCenter);
  row_ = new QWidget;
  auto* rowLayout = new QHBoxLayout(row_);
  rowLayout->setContentsMargins(0, 0, 0, 0);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(title_);
  layout->addWidget(placeholder_, 1);
  layout->addWidget(row_, 1);
  showCharts({}, {});
}

void MeasuredCharts::showCharts(std::vector<QChart*> charts, const QString& title) {
  for (QChartView* view : views_)
    delete view;  // and its chart
  views_.clear();
  for (QChart* chart : charts) {
    styleChartDark(*chart);
    for (QAbstractSeries* series : chart->series()) {
      if (auto* points = qobject_cast<QXYSeries*>(series)) {
        connect(points, &QXYSeries::clicked, this,
                [this, points](const QPointF& value) { pointClicked(points, value); });
      }
    }
    auto* view = new QChartView(chart);
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumSize(360, 320);
    view->setToolTip(tr("Click a point to open its scene and settings in the window"));
    row_->layout()->addWidget(view);
    views_.push_back(view);
  }
  title_->setText(title);
  title_->setVisible(!views_.empty());
  row_->setVisible(!views_.empty());
  placeholder_->setVisible(views_.empty());
}

void MeasuredCharts::setPlaceholder(const QString& placeholder) {
  placeholder_->setText(placeholder);
}

QString MeasuredCharts::placeholder() const {
  return placeholder_->text();
}

void MeasuredCharts::pointClicked(QXYSeries* series, QPointF value) {
  if (const std::optional<std::size_t> index = plots::measurementAt(*series, value))
    emit measurementClicked(*index);
}

}  // namespace fooball::gui
