#pragma once

#include <vector>

#include "fooball/scene.h"
#include "tools/tool_dialog.h"
#include "tradeoff.h"

class QComboBox;
class QLineEdit;
class QListWidget;

namespace fooball::gui {

/// Tools → Speed vs accuracy: what `fooball-cli tradeoff` measures (fooball::measure) on a
/// preset, drawn as the CLI's chart. Clicking a point opens that setting on the scene, as a
/// compare run against the reference backend.
class TradeoffDialog : public ToolDialog {
  Q_OBJECT

 public:
  explicit TradeoffDialog(QWidget* parent = nullptr);

  /// The points of the last run that finished; none after a cancelled one.
  const std::vector<measure::TradeoffPoint>& points() const { return points_; }
  QComboBox* presetBox() const { return preset_; }
  QListWidget* backendList() const { return backends_; }
  QLineEdit* durationEdit() const { return duration_; }
  QLineEdit* compareAtEdit() const { return compareAt_; }

  bool start() override;

 protected:
  void setSettingsEnabled(bool enabled) override;

 private:
  QWidget* createSettings();
  void showPoints(const Scene& scene, const measure::TradeoffSettings& settings,
                  std::vector<measure::TradeoffPoint> points);

  QComboBox* preset_;
  QListWidget* backends_;
  QLineEdit* duration_;
  QLineEdit* compareAt_;

  Scene scene_;         ///< the points' scene
  QString presetName_;  ///< the preset it is
  std::vector<measure::TradeoffPoint> points_;
};

}  // namespace fooball::gui
