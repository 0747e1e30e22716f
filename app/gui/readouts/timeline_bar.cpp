#include "readouts/timeline_bar.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QTimer>

#include "readouts/readout_cells.h"
#include "run/run_controller.h"

namespace fooball::gui {

namespace {

constexpr double kBytesPerMegabyte = 1024.0 * 1024.0;

}  // namespace

TimelineBar::TimelineBar(RunController& runs, QWidget* parent)
    : QWidget(parent), runs_(runs), slider_(new QSlider(Qt::Horizontal)), text_(new QLabel) {
  slider_->setObjectName(QStringLiteral("timeline"));
  slider_->setToolTip(
      tr("Rewind: drag back to any kept moment while paused (',' steps back one); continuing "
         "from there drops the future"));
  slider_->setMinimumWidth(80);
  text_->setObjectName(QStringLiteral("historyBound"));
  text_->setToolTip(
      tr("How much simulated time the rewind history spans, and the memory it holds of its "
         "bound"));
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(slider_, 1);
  layout->addWidget(text_);
  connect(slider_, &QSlider::valueChanged, this, [this](int index) {
    if (!showing_) runs_.rewindTo(std::size_t(index));
  });
  auto* timer = new QTimer(this);
  timer->setInterval(kReadoutRefreshMs);
  connect(timer, &QTimer::timeout, this, &TimelineBar::showHistory);
  timer->start();
  showHistory();
}

void TimelineBar::showHistory() {
  const RunHistory* history = runs_.group().history();
  if (history == nullptr) return;
  showing_ = true;
  slider_->setRange(0, static_cast<int>(history->size()) - 1);
  slider_->setValue(static_cast<int>(history->position()));
  showing_ = false;
  slider_->setEnabled(runs_.paused() && history->size() > 1);
  const double span = history->time(history->size() - 1) - history->time(0);
  // Short, so that the timeline keeps room beside eight runs' status fields at 1000 px.
  text_->setText(tr("history %1 s, %2/%3 MB")
                     .arg(span, 0, 'f', 1)
                     .arg(double(history->bytes()) / kBytesPerMegabyte, 0, 'f', 1)
                     .arg(double(history->bound()) / kBytesPerMegabyte, 0, 'f', 0));
}

QString TimelineBar::text() const {
  return text_->text();
}

}  // namespace fooball::gui
