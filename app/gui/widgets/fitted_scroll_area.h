#pragma once

#include <QScrollArea>

namespace fooball::gui {

/// A vertical scroll area as narrow as its widget's controls allow, beside the scroll bar, and
/// never narrower, or the rightmost column is cut off. The widget's rows may change (a
/// sidebar's with the runs), so the width follows each of its layout requests.
class FittedScrollArea : public QScrollArea {
 public:
  explicit FittedScrollArea(QWidget* widget);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void fitWidth();
};

}  // namespace fooball::gui
