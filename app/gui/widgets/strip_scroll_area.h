#pragma once

#include <QScrollArea>

namespace fooball::gui {

/// A strip that scrolls sideways when its widget is wider than the window allows: as tall as the
/// widget (and its scroll bar, when it shows), as narrow as the layout asks, shown and hidden
/// with the widget. The compare table's columns stay whole in a narrow window instead of holding
/// it wide (eight runs' table is 790 px at least).
class StripScrollArea : public QScrollArea {
 public:
  explicit StripScrollArea(QWidget* widget);

  /// Its height, and no width of its own: the strip takes the width the window's layout gives.
  QSize minimumSizeHint() const override;
  QSize sizeHint() const override;

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

 private:
  void fitHeight();
};

}  // namespace fooball::gui
