#pragma once

#include <QObject>

class QAbstractScrollArea;

namespace fooball::gui {

/// The one owner of the wheel policy for a scrolling column of controls: a slider, spin box or
/// combo box in `area` takes the mouse wheel only when it has the keyboard focus (clicked or
/// tabbed to). Unfocused, the wheel scrolls `area`, so scrolling a sidebar past a control never
/// changes the physics. The wheel gives such a control no focus. It watches the application,
/// so controls added to the area later (a run's options) follow the same policy.
class WheelNeedsFocus : public QObject {
 public:
  explicit WheelNeedsFocus(QAbstractScrollArea& area);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  QAbstractScrollArea& area_;
};

}  // namespace fooball::gui
