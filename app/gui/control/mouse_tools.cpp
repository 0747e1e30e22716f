#include "control/mouse_tools.h"

#include "frames/run_feed.h"
#include "readouts/status_panel.h"
#include "run/run_controller.h"
#include "sidebar/settings_sidebar.h"
#include "view/simulation_view.h"
#include "widgets/user_messages.h"

namespace fooball::gui {

namespace {

QString modeName(MouseMode mode) {
  switch (mode) {
    case MouseMode::Attract:
      return QObject::tr("attract");
    case MouseMode::Repel:
      return QObject::tr("repel");
    case MouseMode::Grab:
      return QObject::tr("grab");
    case MouseMode::Slingshot:
      return QObject::tr("slingshot");
  }
  return {};
}

}  // namespace

MouseTools::MouseTools(Parts parts, QObject* parent) : QObject(parent), parts_(parts) {
  SimulationView* view = &parts_.view;
  RunController& runs = parts_.runs;
  connect(view, &SimulationView::toolPressed, this, &MouseTools::press);
  connect(view, &SimulationView::toolMoved, this, [&runs](Vec2 point) {
    runs.changeTools([&](RunGroup& group) { group.moveTool(point); });
  });
  connect(view, &SimulationView::toolReleased, this, [&runs](Vec2 point) {
    runs.changeTools([&](RunGroup& group) { group.releaseTool(point); });
  });
  connect(view, &SimulationView::attractorPlaced, this, [this](Vec2 point) {
    parts_.runs.changeTools([&](RunGroup& group) { group.addAttractor(point); });
    parts_.sidebar.showAttractorCount(parts_.runs.group().interactions().attractors().size());
    parts_.feed.markChange(tr("attractor"));
  });
  connect(view, &SimulationView::ballClicked, &runs, &RunController::setSelected);
  connect(view, &SimulationView::cursorMoved, this,
          [this](Vec2 point) { parts_.status.showCursor(point.x, point.y); });
}

void MouseTools::press(Vec2 point) {
  const RunGroup& group = parts_.runs.group();
  if (group.interactions().scope == Scope::Selected && !group.selected()) {
    // The tool would act on no ball: say why instead of doing nothing.
    parts_.messages.showStatus(
        tr("The mouse tool acts on the selected ball, and none is selected: "
           "pause (Space) and click a ball, or choose All or Nearest"));
    return;
  }
  parts_.runs.changeTools([&](RunGroup& runGroup) { runGroup.pressTool(point); });
  parts_.feed.markChange(modeName(group.interactions().mode));
}

}  // namespace fooball::gui
