#pragma once

#include <QWidget>
#include <cstddef>
#include <optional>

#include "fooball/interactions.h"
#include "fooball/scene.h"
#include "view/simulation_view.h"

class QButtonGroup;
class QCheckBox;
class QComboBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace fooball::gui {

class BallInspector;
class LogSlider;
class RunCounters;
class RunListEditor;

/// Every setting of the sandbox, each live and showing its value and unit: the scene and its
/// ball count, the runs (RunListEditor), forces and time, collisions, the mouse tool,
/// drawing, and the inspector of the selected ball. It only reports what the user chose; the
/// main window applies it and syncs the sidebar back with the show* slots.
class SettingsSidebar : public QWidget {
  Q_OBJECT

 public:
  explicit SettingsSidebar(QWidget* parent = nullptr);

  /// Spinner limit: the one ball limit, the engine's (fooball/scene.h).
  static constexpr int kMaxBallCount = static_cast<int>(kMaxBalls);

  RunListEditor* runList() const { return runList_; }
  RunCounters* counters() const { return counters_; }
  BallInspector* inspector() const { return inspector_; }
  LogSlider* gravitySlider() const { return gravity_; }
  LogSlider* airResistanceSlider() const { return airResistance_; }
  LogSlider* strengthSlider() const { return strength_; }
  LogSlider* timeScaleSlider() const { return timeScale_; }
  QSpinBox* ballCountBox() const { return ballCount_; }
  QLabel* ballCountRefusal() const { return ballCountRefusal_; }
  QLineEdit* dtField() const { return dt_; }

 public slots:
  /// `presetName` empty: the scene came from a file called `sourceName`.
  void showSceneSource(const QString& presetName, const QString& sourceName);
  void showBallCount(std::size_t count);
  /// Why the last ball count asked for was refused, under the field; empty hides it.
  void showBallCountRefusal(const QString& reason);
  void showWorld(const WorldSettings& world);
  void showStrength(double strength);
  void showTimeScale(double timeScale);
  void showDt(double dt);
  void showMouseMode(MouseMode mode);
  void showScope(Scope scope);
  void showAttractorCount(std::size_t count);
  void showDrawing(bool temperature, bool tethers, bool velocityVectors, bool centreOfMass);
  /// Shows the inspector for ball `index`, or hides it.
  void showSelection(std::optional<std::size_t> index, const BallDef& ball);

 signals:
  void presetChosen(const QString& name);
  void ballCountChosen(int count);
  void restartRequested();
  void resetSceneRequested();

  void gravityChosen(double magnitude);          ///< m/s², pointing the way gravity points now
  void airResistanceChosen(double coefficient);  ///< 1/s
  void strengthChosen(double strength);          ///< 1/s²
  void timeScaleChosen(double timeScale);        ///< simulated seconds per real second
  void dtChosen(double dt);                      ///< s, > 0 and finite
  void resetSlidersRequested();
  void ballCollisionsToggled(bool on);
  /// One wall's box was toggled: `walls` is every wall as the boxes show them now.
  void wallsChosen(const Walls& walls);

  void mouseModeChosen(MouseMode mode);
  void scopeChosen(Scope scope);
  void clearAttractorsRequested();

  void temperatureToggled(bool on);
  void tethersToggled(bool on);
  void velocityVectorsToggled(bool on);
  void centreOfMassToggled(bool on);

 private:
  QGroupBox* createSceneGroup();
  QGroupBox* createForcesGroup();
  QGroupBox* createCollisionsGroup();
  QGroupBox* createMouseGroup();
  QGroupBox* createDrawingGroup();
  /// The time step field was left: emits dtChosen, or says beside it why not.
  void readDt();

  QComboBox* preset_;
  QSpinBox* ballCount_;
  QLabel* ballCountRefusal_;
  RunListEditor* runList_;
  RunCounters* counters_;
  LogSlider* gravity_;
  LogSlider* airResistance_;
  LogSlider* strength_;
  LogSlider* timeScale_;
  QLineEdit* dt_;
  QLabel* dtRefusal_;
  double shownDt_ = kDefaultDt;
  QCheckBox* ballCollisions_;
  /// One box per wall, so a box of three walls (mass-ratio) reads as it is.
  QCheckBox* leftWall_;
  QCheckBox* rightWall_;
  QCheckBox* bottomWall_;
  QCheckBox* topWall_;
  QButtonGroup* mouseMode_;
  QButtonGroup* scope_;
  QPushButton* clearAttractors_;
  QCheckBox* temperature_;
  QCheckBox* tethers_;
  QCheckBox* velocityVectors_;
  QCheckBox* centreOfMass_;
  QGroupBox* inspectorGroup_;
  BallInspector* inspector_;
};

}  // namespace fooball::gui
