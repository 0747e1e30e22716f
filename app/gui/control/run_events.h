#pragma once

#include <QObject>

namespace fooball::gui {

class FrameLoop;
class RunController;
class RunFeed;
class SceneSession;
class SettingsSidebar;
class SimulationView;
class UserMessages;

/// What follows each change the RunController signals: the feed's charts, readouts and markers,
/// the sidebar's run list and ball count, the view, the frame clock, and a word to the user when
/// runs stop or restart. (The title, the status bar and the menus follow in MainWindow.)
class RunEvents : public QObject {
  Q_OBJECT

 public:
  struct Parts {
    RunController& runs;
    RunFeed& feed;
    SimulationView& view;
    SettingsSidebar& sidebar;
    FrameLoop& frames;
    SceneSession& session;
    UserMessages& messages;
  };

  RunEvents(Parts parts, QObject* parent);

 private:
  void connectFailures();

  Parts parts_;
};

}  // namespace fooball::gui
