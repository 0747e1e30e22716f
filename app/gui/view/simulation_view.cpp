#include "view/simulation_view.h"

#include <QMouseEvent>

#include "fooball/presets.h"
#include "run/run_controller.h"
#include "widgets/view_text.h"

namespace fooball::gui {

SimulationView::SimulationView(const RunController& runs, QWidget* parent)
    : QWidget(parent), runs_(runs) {
  setAttribute(Qt::WA_OpaquePaintEvent);
  setMouseTracking(true);
  // A click in the box takes the keyboard from a field of the sidebar, so Space and '.' pause
  // and step instead of typing into it.
  setFocusPolicy(Qt::ClickFocus);
  setCursor(Qt::CrossCursor);
  setToolTip(
      tr("Left button: the mouse tool (attract, repel, grab, slingshot).\n"
         "Right button: place a permanent attractor.\n"
         "Paused: click a ball to select it and edit it in the inspector.\n"
         "Compare mode: run 0 is filled, every other run an outline in its colour."));
}

void SimulationView::setTemperatureColouring(bool on) {
  temperature_ = on;
  update();
}

void SimulationView::setTethers(bool on) {
  tethers_ = on;
  update();
}

void SimulationView::setVelocityVectors(bool on) {
  velocityVectors_ = on;
  update();
}

void SimulationView::setCentreOfMass(bool on) {
  centreOfMass_ = on;
  update();
}

void SimulationView::setCompareLayout(CompareLayout layout) {
  compareLayout_ = layout;
  update();
}

void SimulationView::setLookForShown(bool on) {
  lookForShown_ = on;
  update();
}

void SimulationView::setPreset(const Preset* preset) {
  lookFor_ = preset ? fromView(preset->lookFor) : QString();
  countsCollisions_ = preset && preset->countsCollisions;
  update();
}

void SimulationView::mousePressEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton &&
      lookForCloseButton().contains(event->position().toPoint())) {
    emit lookForClosed();
    return;
  }
  if (inCaptionRows(event->position())) return;  // reading the legend, not using a tool
  const Vec2 point = toMetres(event->position());
  if (event->button() == Qt::RightButton) {
    emit attractorPlaced(point);
  } else if (event->button() == Qt::LeftButton) {
    if (runs_.paused()) {
      emit ballClicked(ballAt(event->position()));
    } else {
      toolHeld_ = true;
      emit toolPressed(point);
    }
  }
  update();
}

void SimulationView::mouseMoveEvent(QMouseEvent* event) {
  const Vec2 point = toMetres(event->position());
  if (toolHeld_) emit toolMoved(point);
  emit cursorMoved(point);
}

void SimulationView::mouseReleaseEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton && toolHeld_) {
    toolHeld_ = false;
    emit toolReleased(toMetres(event->position()));
    update();
  }
}

}  // namespace fooball::gui
