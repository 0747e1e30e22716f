#include "chart_toolbar.h"

#include <QAction>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QToolButton>

#include "flow_layout.h"
#include "toggle_icon.h"

namespace fooball::gui {

namespace {

constexpr double kDefaultWindowSeconds = 20.0;
/// px between switches in a group, and between groups and rows.
constexpr int kToggleSpacing = 2;
constexpr int kGroupSpacing = 10;

}  // namespace

ChartToolBar::ChartToolBar(QWidget* parent) : QWidget(parent) {
  auto* flow = new FlowLayout(this, kGroupSpacing, kToggleSpacing);
  flow->setContentsMargins(4, 2, 4, 2);

  QHBoxLayout* time = addGroup();
  wholeRun_ = addToggle(
      *time, tr("Whole run"),
      tr("Show the whole run (older parts at reduced resolution) instead of a scrolling window"),
      QStringLiteral("wholeRunToggle"));
  wholeRun_->setChecked(false);
  connect(wholeRun_, &QAction::toggled, this, [this](bool whole) {
    windowSpin_->setEnabled(!whole);
    emit wholeRunToggled(whole);
  });

  windowSpin_ = new QDoubleSpinBox(this);
  windowSpin_->setObjectName(QStringLiteral("windowSeconds"));
  windowSpin_->setRange(1.0, 3600.0);
  windowSpin_->setDecimals(0);
  windowSpin_->setSuffix(tr(" s"));
  windowSpin_->setValue(kDefaultWindowSeconds);
  windowSpin_->setKeyboardTracking(false);
  windowSpin_->setToolTip(tr("Length of the scrolling window, in seconds of simulated time"));
  connect(windowSpin_, &QDoubleSpinBox::valueChanged, this, &ChartToolBar::windowSecondsChanged);
  time->addWidget(windowSpin_);

  QHBoxLayout* momentum = addGroup();
  momentumX_ = addQuantityToggle(*momentum, tr("px"), tr("Momentum, x component: Σ m vx (N·s)"),
                                 QStringLiteral("momentumXToggle"));
  momentumY_ = addQuantityToggle(*momentum, tr("py"), tr("Momentum, y component: Σ m vy (N·s)"),
                                 QStringLiteral("momentumYToggle"));
  momentumMagnitude_ =
      addQuantityToggle(*momentum, tr("|p|"), tr("Magnitude of the total momentum |Σ m v| (N·s)"),
                        QStringLiteral("momentumMagnitudeToggle"));
  QHBoxLayout* energy = addGroup();
  kinetic_ = addQuantityToggle(*energy, tr("kinetic"), tr("Kinetic energy Σ ½ m|v|² (J)"),
                               QStringLiteral("kineticToggle"));
  potential_ = addQuantityToggle(*energy, tr("potential"),
                                 tr("Potential energy Σ −m (g·p), zero at the floor y = 0 (J)"),
                                 QStringLiteral("potentialToggle"));
  total_ = addQuantityToggle(*energy, tr("total"), tr("Total energy: kinetic + potential (J)"),
                             QStringLiteral("totalToggle"));
  QHBoxLayout* residual = addGroup();
  residual_ = addQuantityToggle(
      *residual, tr("residual"),
      tr("Energy budget residual: E(t) − E(0) − work by tools and edits + energy taken by drag. "
         "What is left is the method's own error (J)"),
      QStringLiteral("residualToggle"));
  relativeResidual_ = addQuantityToggle(
      *residual, tr("÷|E₀|"),
      tr("Show the residual relative to |E₀|, the run's total energy where its budget began "
         "(load or restart)"),
      QStringLiteral("relativeResidualToggle"));
  {
    const QSignalBlocker blocker(relativeResidual_);  // the toggles are not all there yet
    relativeResidual_->setChecked(false);
  }
  QHBoxLayout* divergence = addGroup();
  divergence_ = addQuantityToggle(
      *divergence, tr("divergence"),
      tr("RMS position difference of every run from run 0, over balls of the same index (m, log "
         "scale), and the chaos baseline's (grey, dashed). Shown with two runs or more, or with "
         "the baseline"),
      QStringLiteral("divergenceToggle"));
}

QHBoxLayout* ChartToolBar::addGroup() {
  auto* group = new QWidget(this);
  auto* row = new QHBoxLayout(group);
  row->setContentsMargins(0, 0, 0, 0);
  row->setSpacing(kToggleSpacing);
  layout()->addWidget(group);
  return row;
}

QAction* ChartToolBar::addToggle(QHBoxLayout& group, const QString& text, const QString& toolTip,
                                 const QString& objectName) {
  // Every action here is a switch: a check box beside its name says which are on.
  auto* toggle = new QAction(text, this);
  toggle->setObjectName(objectName);
  toggle->setToolTip(toolTip);
  toggle->setCheckable(true);
  toggle->setChecked(true);
  toggle->setIcon(toggleIcon());
  addAction(toggle);
  auto* button = new QToolButton;
  button->setDefaultAction(toggle);
  button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  button->setIconSize(QSize(16, 16));
  button->setAutoRaise(true);
  group.addWidget(button);
  return toggle;
}

QAction* ChartToolBar::addQuantityToggle(QHBoxLayout& group, const QString& text,
                                         const QString& toolTip, const QString& objectName) {
  QAction* toggle = addToggle(group, text, toolTip, objectName);
  connect(toggle, &QAction::toggled, this, [this] {
    relativeResidual_->setEnabled(residual_->isChecked());
    emit shownChanged();
  });
  return toggle;
}

ChartToolBar::Shown ChartToolBar::shown() const {
  return {momentumX_->isChecked(), momentumY_->isChecked(),        momentumMagnitude_->isChecked(),
          kinetic_->isChecked(),   potential_->isChecked(),        total_->isChecked(),
          residual_->isChecked(),  relativeResidual_->isChecked(), divergence_->isChecked()};
}

bool ChartToolBar::wholeRun() const {
  return wholeRun_->isChecked();
}

double ChartToolBar::windowSeconds() const {
  return windowSpin_->value();
}

void ChartToolBar::setWholeRun(bool whole) {
  {
    const QSignalBlocker blocker(wholeRun_);
    wholeRun_->setChecked(whole);
  }
  windowSpin_->setEnabled(!whole);
}

void ChartToolBar::setWindowSeconds(double seconds) {
  const QSignalBlocker blocker(windowSpin_);
  windowSpin_->setValue(seconds);  // clamped to the spin box's range
}

}  // namespace fooball::gui
