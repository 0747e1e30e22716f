#include "tools/tool_dialog.h"

#include <QCloseEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include "tools/measured_charts.h"
#include "tools/tool_run_panel.h"

namespace fooball::gui {

ToolDialog::ToolDialog(const QString& placeholder, QWidget* parent) : QDialog(parent) {
  run_ = new ToolRunPanel;
  charts_ = new MeasuredCharts(placeholder);
  connect(run_, &ToolRunPanel::startRequested, this, [this] { start(); });
  connect(run_, &ToolRunPanel::runStarted, this, [this] {
    setSettingsEnabled(false);
    // Until the run ends its charts are not there: say so rather than "Press Start".
    charts_->setPlaceholder(tr("Measuring: the charts appear here when the run has ended"));
    emit runStarted();
  });
  connect(run_, &ToolRunPanel::runFinished, this, [this, placeholder] {
    setSettingsEnabled(true);
    charts_->setPlaceholder(placeholder);
    emit runFinished();
  });
}

void ToolDialog::layOut(const QString& intro, QWidget* settings, QLayout* bottom) {
  auto* introLabel = new QLabel(intro);
  introLabel->setWordWrap(true);
  auto* close = new QPushButton(tr("C&lose"));
  close->setToolTip(tr("Close the dialog; a run still going is cancelled"));
  connect(close, &QPushButton::clicked, this, &QDialog::close);
  auto* buttons = new QHBoxLayout;
  if (bottom) buttons->addLayout(bottom);
  buttons->addStretch(1);
  buttons->addWidget(close);

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(introLabel);
  layout->addWidget(settings);
  layout->addWidget(run_);
  layout->addWidget(charts_, 1);
  layout->addLayout(buttons);
}

void ToolDialog::closeEvent(QCloseEvent* event) {
  run_->stopAndJoin();
  QDialog::closeEvent(event);
}

void ToolDialog::reject() {
  run_->stopAndJoin();
  QDialog::reject();
}

}  // namespace fooball::gui
