#include "sidebar/settings_sidebar.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QRadioButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>
#include <cmath>

#include "fooball/number_text.h"
#include "fooball/presets.h"
#include "readouts/run_counters.h"
#include "sidebar/ball_inspector.h"
#include "sidebar/run_list_editor.h"
#include "widgets/log_slider.h"
#include "widgets/number_format.h"
#include "widgets/view_text.h"

namespace fooball::gui {

namespace {

/// A label above a full-width control, with the label as its buddy for keyboard access.
void addLabelled(QVBoxLayout* layout, const QString& text, QWidget* control,
                 const QString& toolTip) {
  auto* label = new QLabel(text);
  label->setBuddy(control);
  label->setToolTip(toolTip);
  control->setToolTip(toolTip);
  layout->addWidget(label);
  layout->addWidget(control);
}

QRadioButton* addRadio(QButtonGroup* group, int id, const QString& text, const QString& toolTip) {
  auto* button = new QRadioButton(text);
  button->setObjectName(QString(text).remove(QLatin1Char(' ')).toLower() + QStringLiteral("Radio"));
  button->setToolTip(toolTip);
  group->addButton(button, id);
  return button;
}

}  // namespace

SettingsSidebar::SettingsSidebar(QWidget* parent) : QWidget(parent) {
  inspector_ = new BallInspector;
  inspectorGroup_ = new QGroupBox(tr("Selected ball"));
  inspectorGroup_->setToolTip(tr("Pause (Space) and click a ball to select it"));
  auto* inspectorLayout = new QVBoxLayout(inspectorGroup_);
  inspectorLayout->addWidget(inspector_);
  inspectorGroup_->hide();

  // The inspector comes first: selecting a ball is when the user looks here.
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(inspectorGroup_);
  layout->addWidget(createSceneGroup());
  runList_ = new RunListEditor;
  layout->addWidget(runList_);
  counters_ = new RunCounters;
  layout->addWidget(counters_);
  layout->addWidget(createForcesGroup());
  layout->addWidget(createCollisionsGroup());
  layout->addWidget(createMouseGroup());
  layout->addWidget(createDrawingGroup());
  layout->addStretch(1);
}

QGroupBox* SettingsSidebar::createSceneGroup() {
  auto* group = new QGroupBox(tr("Scene"));
  auto* layout = new QVBoxLayout(group);

  preset_ = new QComboBox;
  preset_->setObjectName(QStringLiteral("presetBox"));
  for (const Preset& preset : presets()) {
    preset_->addItem(fromView(preset.name));
    preset_->setItemData(preset_->count() - 1, fromView(preset.description), Qt::ToolTipRole);
  }
  addLabelled(layout, tr("&Preset:"), preset_,
              tr("Built-in scenes; choosing one starts it from t = 0 in every run"));
  connect(preset_, &QComboBox::activated, this,
          [this](int index) { emit presetChosen(preset_->itemText(index)); });

  ballCount_ = new QSpinBox;
  ballCount_->setObjectName(QStringLiteral("ballCountBox"));
  ballCount_->setRange(0, kMaxBallCount);
  ballCount_->setGroupSeparatorShown(true);
  ballCount_->setSuffix(tr(" balls"));
  ballCount_->setKeyboardTracking(false);
  ballCount_->setAccelerated(true);
  addLabelled(layout, tr("&Number of balls:"), ballCount_,
              tr("More balls are placed where there is room, sized like the balls already "
                 "there; fewer removes the newest"));
  connect(ballCount_, &QSpinBox::valueChanged, this, &SettingsSidebar::ballCountChosen);
  ballCountRefusal_ = new QLabel;
  ballCountRefusal_->setObjectName(QStringLiteral("ballCountRefusal"));
  ballCountRefusal_->setWordWrap(true);
  ballCountRefusal_->setStyleSheet(QStringLiteral("color: #ffb347"));
  ballCountRefusal_->hide();
  layout->addWidget(ballCountRefusal_);

  auto* restart = new QPushButton(tr("Restart"));
  restart->setToolTip(
      tr("Back to the loaded scene at t = 0, keeping the current settings (Ctrl+R)"));
  connect(restart, &QPushButton::clicked, this, &SettingsSidebar::restartRequested);
  auto* reset = new QPushButton(tr("Reset scene"));
  reset->setToolTip(
      tr("The loaded scene exactly as loaded: its balls and settings, sliders back to their "
         "defaults, attractors cleared (Ctrl+Shift+R)"));
  connect(reset, &QPushButton::clicked, this, &SettingsSidebar::resetSceneRequested);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(restart);
  buttons->addWidget(reset);
  layout->addLayout(buttons);
  return group;
}

QGroupBox* SettingsSidebar::createForcesGroup() {
  auto* group = new QGroupBox(tr("Forces and time"));
  auto* layout = new QVBoxLayout(group);

  gravity_ = new LogSlider({0.01, 100.0, true}, [](double g) {
    return g == 0.0 ? tr("off") : formatNumber(g) + QStringLiteral(" m/s²");
  });
  gravity_->setObjectName(QStringLiteral("gravitySlider"));
  addLabelled(layout, tr("&Gravity:"), gravity_,
              tr("Acceleration of gravity in m/s² (Earth: 9.81), left end off; logarithmic"));
  connect(gravity_, &LogSlider::valueChanged, this, &SettingsSidebar::gravityChosen);

  airResistance_ = new LogSlider({0.001, 10.0, true}, [](double c) {
    return c == 0.0 ? tr("off") : formatNumber(c) + QStringLiteral(" 1/s");
  });
  airResistance_->setObjectName(QStringLiteral("airResistanceSlider"));
  addLabelled(layout, tr("&Air resistance:"), airResistance_,
              tr("Linear drag dv/dt = −c·v, c in 1/s, left end off; logarithmic"));
  connect(airResistance_, &LogSlider::valueChanged, this, &SettingsSidebar::airResistanceChosen);

  strength_ = new LogSlider({0.1, 1000.0, true}, [](double k) {
    return k == 0.0 ? tr("off") : formatNumber(k) + QStringLiteral(" 1/s²");
  });
  strength_->setObjectName(QStringLiteral("strengthSlider"));
  addLabelled(layout, tr("&Mouse strength:"), strength_,
              tr("Attract/repel pull in m/s² per metre from the cursor (also attractors and the "
                 "slingshot), left end off; logarithmic"));
  connect(strength_, &LogSlider::valueChanged, this, &SettingsSidebar::strengthChosen);

  timeScale_ = new LogSlider({0.05, 8.0, false},
                             [](double s) { return formatNumber(s) + QStringLiteral("×"); });
  timeScale_->setObjectName(QStringLiteral("timeScaleSlider"));
  addLabelled(layout, tr("&Simulation speed:"), timeScale_,
              tr("Simulated seconds per real second; right is faster. The time step stays "
                 "the same, so results do not depend on it"));
  connect(timeScale_, &LogSlider::valueChanged, this, &SettingsSidebar::timeScaleChosen);

  dt_ = new QLineEdit;
  dt_->setObjectName(QStringLiteral("dtField"));
  addLabelled(layout, tr("&Time step (dt, s):"), dt_,
              tr("The physics time step in seconds, as fooball-cli's --dt: any positive number "
                 "(the default is 1/60). Smaller is more accurate and takes more steps per "
                 "simulated second. Saved with the scene and reopened with it"));
  connect(dt_, &QLineEdit::editingFinished, this, &SettingsSidebar::readDt);
  dtRefusal_ = new QLabel;
  dtRefusal_->setObjectName(QStringLiteral("dtRefusal"));
  dtRefusal_->setWordWrap(true);
  dtRefusal_->setStyleSheet(ballCountRefusal_->styleSheet());
  dtRefusal_->hide();
  layout->addWidget(dtRefusal_);

  auto* reset = new QPushButton(tr("Reset sliders"));
  reset->setToolTip(
      tr("Gravity and air resistance back to the scene's own values, mouse "
         "strength to 10 1/s², speed to 1×"));
  connect(reset, &QPushButton::clicked, this, &SettingsSidebar::resetSlidersRequested);
  layout->addWidget(reset);
  return group;
}

QGroupBox* SettingsSidebar::createCollisionsGroup() {
  auto* group = new QGroupBox(tr("Collisions"));
  auto* layout = new QVBoxLayout(group);
  ballCollisions_ = new QCheckBox(tr("Ball–ball collisions"));
  ballCollisions_->setObjectName(QStringLiteral("ballCollisionsBox"));
  ballCollisions_->setToolTip(
      tr("Off: balls pass through each other (and cost no collision work)"));
  connect(ballCollisions_, &QCheckBox::toggled, this, &SettingsSidebar::ballCollisionsToggled);
  layout->addWidget(ballCollisions_);

  auto* wallsLabel = new QLabel(tr("Walls:"));
  wallsLabel->setToolTip(tr("A wall that is off lets balls leave the box (dashed edge)"));
  layout->addWidget(wallsLabel);
  auto* walls = new QGridLayout;
  const auto addWall = [&](QCheckBox*& box, const QString& text, const QString& name, int row,
                           int column) {
    box = new QCheckBox(text);
    box->setObjectName(name);
    box->setToolTip(tr("Off: balls leave the box through the %1 wall and are gone from view")
                        .arg(text.toLower()));
    connect(box, &QCheckBox::toggled, this, [this] {
      emit wallsChosen(Walls{leftWall_->isChecked(), rightWall_->isChecked(),
                             bottomWall_->isChecked(), topWall_->isChecked()});
    });
    walls->addWidget(box, row, column);
  };
  addWall(leftWall_, tr("Left"), QStringLiteral("leftWallBox"), 0, 0);
  addWall(rightWall_, tr("Right"), QStringLiteral("rightWallBox"), 0, 1);
  addWall(bottomWall_, tr("Bottom"), QStringLiteral("bottomWallBox"), 1, 0);
  addWall(topWall_, tr("Top"), QStringLiteral("topWallBox"), 1, 1);
  layout->addLayout(walls);
  return group;
}

QGroupBox* SettingsSidebar::createMouseGroup() {
  auto* group = new QGroupBox(tr("Mouse tool"));
  auto* layout = new QVBoxLayout(group);

  auto* modes = new QGridLayout;
  mouseMode_ = new QButtonGroup(this);
  modes->addWidget(addRadio(mouseMode_, int(MouseMode::Attract), tr("Attract"),
                            tr("Hold the left button: balls are pulled towards the cursor")),
                   0, 0);
  modes->addWidget(addRadio(mouseMode_, int(MouseMode::Repel), tr("Repel"),
                            tr("Hold the left button: balls are pushed away from the cursor")),
                   0, 1);
  modes->addWidget(addRadio(mouseMode_, int(MouseMode::Grab), tr("Grab"),
                            tr("Press on a ball and drag it; it follows the cursor")),
                   1, 0);
  modes->addWidget(addRadio(mouseMode_, int(MouseMode::Slingshot), tr("Slingshot"),
                            tr("Press near a ball, pull back and release: it flies the other "
                               "way, faster the further you pull")),
                   1, 1);
  connect(mouseMode_, &QButtonGroup::idClicked, this,
          [this](int id) { emit mouseModeChosen(static_cast<MouseMode>(id)); });
  auto* modeLabel = new QLabel(tr("Mode:"));
  modeLabel->setToolTip(tr("What the left mouse button does in the box"));
  layout->addWidget(modeLabel);
  layout->addLayout(modes);

  auto* scopes = new QHBoxLayout;
  scope_ = new QButtonGroup(this);
  scopes->addWidget(
      addRadio(scope_, int(Scope::All), tr("All"), tr("The tool acts on every ball")));
  scopes->addWidget(addRadio(scope_, int(Scope::Nearest), tr("Nearest"),
                             tr("The tool acts on the ball nearest to where you press")));
  scopes->addWidget(addRadio(scope_, int(Scope::Selected), tr("Selected"),
                             tr("The tool acts on the selected ball (pause and click one)")));
  connect(scope_, &QButtonGroup::idClicked, this,
          [this](int id) { emit scopeChosen(static_cast<Scope>(id)); });
  auto* scopeLabel = new QLabel(tr("Acts on:"));
  scopeLabel->setToolTip(tr("Which balls the mouse tool moves; attractors always act on all"));
  layout->addWidget(scopeLabel);
  layout->addLayout(scopes);

  clearAttractors_ = new QPushButton;
  clearAttractors_->setToolTip(tr("Remove every permanent attractor (Ctrl+Backspace)"));
  connect(clearAttractors_, &QPushButton::clicked, this,
          &SettingsSidebar::clearAttractorsRequested);
  layout->addWidget(clearAttractors_);
  showAttractorCount(0);

  auto* tip =
      new QLabel(tr("<b>Tip:</b> right-click places a permanent attractor. Pause with "
                    "Space and click a ball to edit it."));
  tip->setWordWrap(true);
  tip->setToolTip(tr("Mouse and keys are listed under Help"));
  layout->addWidget(tip);
  return group;
}

QGroupBox* SettingsSidebar::createDrawingGroup() {
  auto* group = new QGroupBox(tr("Drawing"));
  auto* layout = new QVBoxLayout(group);
  const auto addBox = [&](QCheckBox*& box, const QString& text, const QString& toolTip,
                          void (SettingsSidebar::*signal)(bool)) {
    box = new QCheckBox(text);
    box->setToolTip(toolTip);
    connect(box, &QCheckBox::toggled, this, signal);
    layout->addWidget(box);
  };
  addBox(temperature_, tr("Temperature colouring"),
         tr("Colour balls by speed, blue (slow) to red (fast); the legend gives the scale"),
         &SettingsSidebar::temperatureToggled);
  addBox(tethers_, tr("Tethers"),
         tr("Lines from the cursor and from attractors to the balls they pull"),
         &SettingsSidebar::tethersToggled);
  addBox(velocityVectors_, tr("Velocity vectors"),
         tr("A line from each ball's centre along its velocity: where it will be in 0.25 s"),
         &SettingsSidebar::velocityVectorsToggled);
  addBox(centreOfMass_, tr("Centre of mass"), tr("A crosshair at the centre of mass of each run"),
         &SettingsSidebar::centreOfMassToggled);
  return group;
}

void SettingsSidebar::showSceneSource(const QString& presetName, const QString& sourceName) {
  const int index = presetName.isEmpty() ? -1 : preset_->findText(presetName);
  preset_->setPlaceholderText(sourceName);
  preset_->setCurrentIndex(index);
}

void SettingsSidebar::showBallCount(std::size_t count) {
  const QSignalBlocker blocker(ballCount_);
  ballCount_->setValue(static_cast<int>(std::min<std::size_t>(count, kMaxBallCount)));
}

void SettingsSidebar::showBallCountRefusal(const QString& reason) {
  ballCountRefusal_->setText(reason);
  ballCountRefusal_->setVisible(!reason.isEmpty());
}

void SettingsSidebar::showWorld(const WorldSettings& world) {
  gravity_->setValue(length(world.gravity));
  airResistance_->setValue(world.airResistance);
  const QSignalBlocker collisionsBlocker(ballCollisions_);
  ballCollisions_->setChecked(world.ballCollisions);
  for (auto [box, on] :
       {std::pair{leftWall_, world.walls.left}, std::pair{rightWall_, world.walls.right},
        std::pair{bottomWall_, world.walls.bottom}, std::pair{topWall_, world.walls.top}}) {
    const QSignalBlocker blocker(box);
    box->setChecked(on);
  }
}

void SettingsSidebar::showStrength(double strength) {
  strength_->setValue(strength);
}

void SettingsSidebar::showTimeScale(double timeScale) {
  timeScale_->setValue(timeScale);
}

void SettingsSidebar::showDt(double dt) {
  shownDt_ = dt;
  dt_->setText(QString::fromStdString(exactNumberText(dt)));
}

void SettingsSidebar::readDt() {
  const QString text = dt_->text().trimmed();
  if (text == QString::fromStdString(exactNumberText(shownDt_))) return;  // left as it was
  bool ok = false;
  const double dt = QLocale::c().toDouble(text, &ok);
  if (!ok || !std::isfinite(dt) || !(dt > 0.0)) {
    dtRefusal_->setText(
        tr("“%1” is no time step: a positive number of seconds, e.g. 0.001").arg(text));
    dtRefusal_->show();
    showDt(shownDt_);
    return;
  }
  dtRefusal_->hide();
  emit dtChosen(dt);
}

void SettingsSidebar::showMouseMode(MouseMode mode) {
  mouseMode_->button(int(mode))->setChecked(true);
}

void SettingsSidebar::showScope(Scope scope) {
  scope_->button(int(scope))->setChecked(true);
}

void SettingsSidebar::showAttractorCount(std::size_t count) {
  clearAttractors_->setText(tr("Clear attractors (%1)").arg(count));
  clearAttractors_->setEnabled(count > 0);
}

void SettingsSidebar::showDrawing(bool temperature, bool tethers, bool velocityVectors,
                                  bool centreOfMass) {
  temperature_->setChecked(temperature);
  tethers_->setChecked(tethers);
  velocityVectors_->setChecked(velocityVectors);
  centreOfMass_->setChecked(centreOfMass);
}

void SettingsSidebar::showSelection(std::optional<std::size_t> index, const BallDef& ball) {
  inspectorGroup_->setVisible(index.has_value());
  if (index) inspector_->showBall(*index, ball);
}

}  // namespace fooball::gui
