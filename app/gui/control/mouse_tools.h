#pragma once

#include <QObject>

#include "fooball/vec2.h"

namespace fooball::gui {

class RunController;
class RunFeed;
class SettingsSidebar;
class SimulationView;
class StatusPanel;
class UserMessages;

/// What the mouse does on the simulation view: the mouse tool (with a chart marker for each
/// press), permanent attractors, selecting a ball while paused, and the cursor's position in the
/// status bar.
class MouseTools : public QObject {
  Q_OBJECT

 public:
  struct Parts {
    SimulationView& view;
    RunController& runs;
    RunFeed& feed;
    SettingsSidebar& sidebar;  ///< shows the attractors' count
    StatusPanel& status;
    UserMessages& messages;
  };

  MouseTools(Parts parts, QObject* parent);

 private:
  void press(Vec2 point);

  Parts parts_;
};

}  // namespace fooball::gui
