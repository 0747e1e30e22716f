#pragma once

#include <QDialog>
#include <QString>

#include "tools/configuration.h"

class QLabel;
class QLayout;

namespace fooball::gui {

class MeasuredCharts;
class ToolRunPanel;

/// What Tools → Speed vs accuracy and Tools → Failure map share: an introduction, the
/// measurement's settings, a ToolRunPanel (a worker thread, progress, Cancel), the CLI's charts
/// whose points open their configuration in the window, and Close, which cancels a run.
class ToolDialog : public QDialog {
  Q_OBJECT

 public:
  ToolRunPanel* runPanel() const { return run_; }
  MeasuredCharts* charts() const { return charts_; }

  /// Checks the settings and starts the run; on bad settings shows one error and starts
  /// nothing. Returns whether a run started.
  virtual bool start() = 0;

 signals:
  /// A run starts or has ended (finished, cancelled or failed): the app pauses its own
  /// simulation in between, since both would share the CPU.
  void runStarted();
  void runFinished();
  /// A chart's point was clicked: open what it measured.
  void openRequested(const Configuration& configuration);

 protected:
  /// `placeholder`: what the charts' place says before there are any.
  ToolDialog(const QString& placeholder, QWidget* parent);
  /// Lays the dialog out: `intro`, `settings`, the run panel, the charts, then `bottom` (may be
  /// null) beside Close.
  void layOut(const QString& intro, QWidget* settings, QLayout* bottom);
  /// The settings are fixed while a run goes.
  virtual void setSettingsEnabled(bool enabled) = 0;
  void closeEvent(QCloseEvent* event) override;
  void reject() override;

 private:
  ToolRunPanel* run_;
  MeasuredCharts* charts_;
};

}  // namespace fooball::gui
