#pragma once

#include <vector>

#include "failure_map.h"
#include "tools/tool_dialog.h"

class QCheckBox;
class QComboBox;
class QListWidget;

namespace fooball::gui {

/// Tools → Failure map: the sweeps of `fooball-cli failure-map` (fooball::failure_map), each
/// drawn as the CLI's chart. Clicking a point opens the sweep's scene at that point on its
/// backend, as a compare run against the reference backend.
class FailureMapDialog : public ToolDialog {
  Q_OBJECT

 public:
  explicit FailureMapDialog(QWidget* parent = nullptr);

  /// Every point of the last run that finished, sweep by sweep; none after a cancelled one.
  const std::vector<failure_map::SweepPoint>& points() const { return points_; }
  /// The points of the sweep on show, in the order its charts index them.
  const std::vector<failure_map::SweepPoint>& shownPoints() const { return shown_; }
  QListWidget* sweepList() const { return sweeps_; }
  QListWidget* backendList() const { return backends_; }
  QCheckBox* quickBox() const { return quick_; }
  /// Which of the sweeps run the charts show.
  QComboBox* shownSweepBox() const { return shownSweep_; }

  bool start() override;

 protected:
  void setSettingsEnabled(bool enabled) override;

 private:
  QWidget* createSettings();
  void showPoints(std::vector<failure_map::SweepPoint> points);
  void showSweep(const QString& name);

  QListWidget* sweeps_;
  QListWidget* backends_;
  QCheckBox* quick_;
  QComboBox* shownSweep_;

  std::vector<failure_map::SweepPoint> points_;
  std::vector<failure_map::SweepPoint> shown_;
};

}  // namespace fooball::gui
