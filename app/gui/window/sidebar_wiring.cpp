#include "window/sidebar_wiring.h"

#include <QStringList>
#include <stdexcept>

#include "charts/chart_panel.h"
#include "fooball/number_text.h"
#include "frames/frame_loop.h"
#include "frames/run_feed.h"
#include "readouts/status_panel.h"
#include "run/run_controller.h"
#include "sidebar/ball_inspector.h"
#include "sidebar/run_list_editor.h"
#include "sidebar/settings_sidebar.h"
#include "view/simulation_view.h"
#include "widgets/number_format.h"
#include "window/ball_commands.h"
#include "window/main_window.h"
#include "window/scene_commands.h"
#include "window/window_actions.h"

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

/// The chart marker for a change of walls: "left wall off", "top wall on".
QString wallsChangeLabel(const Walls& before, const Walls& after) {
  QStringList changes;
  const auto add = [&](bool was, bool is, const QString& wall) {
    if (was != is)
      changes.append(is ? QObject::tr("%1 wall on").arg(wall)
                        : QObject::tr("%1 wall off").arg(wall));
  };
  add(before.left, after.left, QObject::tr("left"));
  add(before.right, after.right, QObject::tr("right"));
  add(before.bottom, after.bottom, QObject::tr("bottom"));
  add(before.top, after.top, QObject::tr("top"));
  return changes.join(QStringLiteral(", "));
}

/// Changes the world settings of every run; `edit` adjusts a copy of today's.
template <class Edit>
void changeWorld(MainWindow& window, Edit&& edit) {
  WorldSettings world = window.runs().group().world();
  edit(world);
  window.runs().change([&](RunGroup& group) { group.setWorld(world); });
}

void applyGravity(MainWindow& window, double magnitude) {
  const RunGroup& group = window.runs().group();
  // Keep the direction gravity has (or had in the scene); straight down when there is none.
  Vec2 direction{0.0, -1.0};
  const Vec2 now = group.world().gravity;
  const Vec2 loaded = group.loadedScene().world.gravity;
  if (length(now) > 0.0) {
    direction = now / length(now);
  } else if (length(loaded) > 0.0) {
    direction = loaded / length(loaded);
  }
  changeWorld(window, [&](WorldSettings& world) { world.gravity = magnitude * direction; });
  window.feed().markChange(QObject::tr("gravity %1 m/s²").arg(formatNumber(magnitude)),
                           QStringLiteral("gravity"));
}

/// A new run; every run restarts from run 0's state (RunController::runsRestarted marks it).
void addRun(MainWindow& window, const RunSpec& spec) {
  RunController& runs = window.runs();
  const bool wasComparing = runs.comparing();
  try {
    runs.addRun(spec);
  } catch (const std::invalid_argument& error) {
    window.showStatus(QString::fromStdString(error.what()));
    return;
  }
  if (!wasComparing) runs.setBaseline(true);  // compare mode shows chaos unless hidden
  window.feed().addRun();
  window.showRuns();
}

void removeRun(MainWindow& window, int index) {
  if (window.runs().runCount() < 2) return;
  window.runs().removeRun(index);
  window.feed().removeRun(index);
  window.feed().markChange(QObject::tr("run %1 removed").arg(index));
}

/// Run `index` continues on `backend` (its default options) from its own state.
void setRunBackend(MainWindow& window, int index, const QString& backend) {
  RunController& runs = window.runs();
  if (backend.toStdString() == runs.group().spec(std::size_t(index)).backend) return;
  try {
    runs.setRunSpec(index, RunSpec{backend.toStdString(), {}});
  } catch (const std::invalid_argument& error) {
    window.showStatus(QString::fromStdString(error.what()));
    window.showRuns();
    return;
  }
  window.feed().renameRun(index);
  window.feed().markChange(QObject::tr("run %1 → %2").arg(index).arg(backend));
}

void wireRunList(MainWindow& window) {
  RunListEditor* list = window.sidebar()->runList();
  QObject::connect(list, &RunListEditor::backendChosen, &window,
                   [&window](int run, const QString& name) { setRunBackend(window, run, name); });
  QObject::connect(list, &RunListEditor::addRunRequested, &window, [&window](const QString& name) {
    addRun(window, RunSpec{name.toStdString(), {}});
  });
  QObject::connect(list, &RunListEditor::removeRunRequested, &window,
                   [&window](int run) { removeRun(window, run); });
  QObject::connect(
      list, &RunListEditor::optionChanged, &window,
      [&window](int run, const QString& name, double value) {
        try {
          window.runs().setBackendOption(run, name, value);
          // The value as the run spec has it: "substeps = 8", "rest_bounce_time =
          // 1e-06".
          window.feed().markChange(
              QStringLiteral("%1 = %2").arg(name, QString::fromStdString(exactNumberText(value))),
              QStringLiteral("run %1 %2").arg(run).arg(name));
        } catch (const std::invalid_argument& error) {
          window.showStatus(QString::fromStdString(error.what()));
          window.sidebar()->runList()->showRuns(window.runs().group());
        }
      });
  QObject::connect(list, &RunListEditor::baselineToggled, &window, [&window](bool on) {
    window.runs().setBaseline(on);
    window.feed().showBaseline(on);
    window.feed().markChange(on ? QObject::tr("baseline on") : QObject::tr("baseline off"));
  });
  QObject::connect(list, &RunListEditor::compareLayoutChosen, &window,
                   [&window](CompareLayout layout) {
                     WindowActions& actions = window.actions();
                     (layout == CompareLayout::Overlay ? actions.overlay() : actions.sideBySide())
                         ->setChecked(true);
                     window.view()->setCompareLayout(layout);
                   });
}

void wireInspector(MainWindow& window) {
  BallInspector* inspector = window.sidebar()->inspector();
  QObject::connect(inspector, &BallInspector::ballEdited, &window,
                   [&window](std::size_t index, const BallDef& ball) {
                     editBall(window, index, ball);
                     window.view()->update();
                   });
  QObject::connect(inspector, &BallInspector::deleteRequested, &window,
                   [&window](std::size_t index) { deleteBall(window, index); });
}

}  // namespace

void wireSidebar(MainWindow& window) {
  SettingsSidebar* s = window.sidebar();
  MainWindow* w = &window;
  QObject::connect(s, &SettingsSidebar::presetChosen, w,
                   [w](const QString& name) { openPreset(*w, name); });
  QObject::connect(s, &SettingsSidebar::ballCountChosen, w,
                   [w](int count) { setBallCount(*w, static_cast<std::size_t>(count)); });
  QObject::connect(s, &SettingsSidebar::restartRequested, w, &MainWindow::restart);
  QObject::connect(s, &SettingsSidebar::resetSceneRequested, w, &MainWindow::resetScene);

  QObject::connect(s, &SettingsSidebar::gravityChosen, w,
                   [w](double magnitude) { applyGravity(*w, magnitude); });
  QObject::connect(s, &SettingsSidebar::airResistanceChosen, w, [w](double coefficient) {
    changeWorld(*w, [&](WorldSettings& world) { world.airResistance = coefficient; });
    w->feed().markChange(QObject::tr("air resistance %1 1/s").arg(formatNumber(coefficient)),
                         QStringLiteral("air resistance"));
  });
  QObject::connect(s, &SettingsSidebar::strengthChosen, w, [w](double strength) {
    w->runs().changeTools([&](RunGroup& group) { group.setStrength(strength); });
    w->feed().markChange(QObject::tr("mouse strength %1").arg(formatNumber(strength)),
                         QStringLiteral("mouse strength"));
  });
  QObject::connect(s, &SettingsSidebar::timeScaleChosen, w, [w](double timeScale) {
    w->frames().setTimeScale(timeScale);
    w->feed().markChange(QObject::tr("speed %1×").arg(formatNumber(timeScale)),
                         QStringLiteral("speed"));
  });
  QObject::connect(s, &SettingsSidebar::resetSlidersRequested, w, [w] { resetSliders(*w); });
  QObject::connect(s, &SettingsSidebar::ballCollisionsToggled, w, [w](bool on) {
    changeWorld(*w, [&](WorldSettings& world) { world.ballCollisions = on; });
    w->feed().markChange(on ? QObject::tr("collisions on") : QObject::tr("collisions off"));
  });
  QObject::connect(s, &SettingsSidebar::wallsChosen, w, [w](const Walls& walls) {
    const QString label = wallsChangeLabel(w->runs().group().world().walls, walls);
    changeWorld(*w, [&](WorldSettings& world) { world.walls = walls; });
    w->feed().markChange(label);
    w->view()->update();
  });

  QObject::connect(s, &SettingsSidebar::mouseModeChosen, w, [w](MouseMode mode) {
    w->runs().changeTools([&](RunGroup& group) { group.setMouseMode(mode); });
  });
  QObject::connect(s, &SettingsSidebar::scopeChosen, w, [w](Scope scope) {
    w->runs().changeTools([&](RunGroup& group) { group.setScope(scope); });
  });
  QObject::connect(s, &SettingsSidebar::clearAttractorsRequested, w, [w] { clearAttractors(*w); });

  // The drawing check boxes and the View menu's actions mirror each other.
  const WindowActions& actions = window.actions();
  QObject::connect(s, &SettingsSidebar::temperatureToggled, actions.temperature(),
                   &QAction::setChecked);
  QObject::connect(s, &SettingsSidebar::tethersToggled, actions.tethers(), &QAction::setChecked);
  QObject::connect(s, &SettingsSidebar::velocityVectorsToggled, actions.velocityVectors(),
                   &QAction::setChecked);
  QObject::connect(s, &SettingsSidebar::centreOfMassToggled, actions.centreOfMass(),
                   &QAction::setChecked);
  wireRunList(window);
  wireInspector(window);
}

void wireView(MainWindow& window) {
  SimulationView* view = window.view();
  MainWindow* w = &window;
  QObject::connect(view, &SimulationView::toolPressed, w, [w](Vec2 point) {
    const Interactions& tools = w->runs().group().interactions();
    if (tools.scope == Scope::Selected && !w->runs().group().selected()) {
      // The tool would act on no ball: say why instead of doing nothing.
      w->showStatus(
          QObject::tr("The mouse tool acts on the selected ball, and none is selected: "
                      "pause (Space) and click a ball, or choose All or Nearest"));
      return;
    }
    w->runs().changeTools([&](RunGroup& group) { group.pressTool(point); });
    w->feed().markChange(modeName(w->runs().group().interactions().mode));
  });
  QObject::connect(view, &SimulationView::toolMoved, w, [w](Vec2 point) {
    w->runs().changeTools([&](RunGroup& group) { group.moveTool(point); });
  });
  QObject::connect(view, &SimulationView::toolReleased, w, [w](Vec2 point) {
    w->runs().changeTools([&](RunGroup& group) { group.releaseTool(point); });
  });
  QObject::connect(view, &SimulationView::attractorPlaced, w, [w](Vec2 point) {
    w->runs().changeTools([&](RunGroup& group) { group.addAttractor(point); });
    w->sidebar()->showAttractorCount(w->runs().group().interactions().attractors().size());
    w->feed().markChange(QObject::tr("attractor"));
  });
  QObject::connect(view, &SimulationView::ballClicked, &window.runs(), &RunController::setSelected);
  QObject::connect(view, &SimulationView::cursorMoved, w,
                   [w](Vec2 point) { w->status().showCursor(point.x, point.y); });
}

void resetSliders(MainWindow& window) {
  const Scene& loaded = window.runs().group().loadedScene();
  changeWorld(window, [&](WorldSettings& world) {
    world.gravity = loaded.world.gravity;
    world.airResistance = loaded.world.airResistance;
  });
  window.runs().changeTools(
      [](RunGroup& group) { group.setStrength(Interactions::kDefaultStrength); });
  window.frames().setTimeScale(FrameLoop::kDefaultTimeScale);
  SettingsSidebar* sidebar = window.sidebar();
  sidebar->showWorld(window.runs().group().world());
  sidebar->showStrength(Interactions::kDefaultStrength);
  sidebar->showTimeScale(FrameLoop::kDefaultTimeScale);
  window.feed().markChange(QObject::tr("sliders reset"));
}

void clearAttractors(MainWindow& window) {
  window.runs().changeTools([](RunGroup& group) { group.clearAttractors(); });
  window.sidebar()->showAttractorCount(0);
  window.view()->update();
}

}  // namespace fooball::gui
