#pragma once

#include <QObject>

class QAbstractSpinBox;
class QDoubleSpinBox;
class QKeyEvent;
class QWidget;

namespace fooball::gui {

/// True while the user is typing a number into `field`: its text is not its value's any more
/// (the app's fields take the value when the edit finishes, not while typing).
bool isBeingEdited(const QDoubleSpinBox& field);

/// Keeps the keyboard with the app while one of its number fields merely has focus. A field
/// given focus takes every printable key as text, so Space and '.' would type into it instead of
/// pausing and stepping. This event filter, on the application because the fields come and go
/// (a run's options form), gives such a key to the app's shortcut instead, and never to the
/// field, when it is a shortcut of one of `window`'s actions and
/// - it can be no part of a number (Space), or
/// - it can ('.'), but the user is not typing into the field (isBeingEdited): "0.5" still types.
/// Editing keys (Delete, Backspace, arrows) stay with the field. Enter finishes an edit and gives
/// the keyboard back to `home` (the box); a field left by clicking elsewhere leaves it there.
class NumberFieldKeys : public QObject {
 public:
  NumberFieldKeys(QWidget& window, QWidget& home);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  bool isAppKey(const QAbstractSpinBox& field, const QKeyEvent& key) const;
  bool isShortcut(const QKeyEvent& key) const;

  QWidget& window_;
  QWidget& home_;
};

}  // namespace fooball::gui
