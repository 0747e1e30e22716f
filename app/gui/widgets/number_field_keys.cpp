#include "widgets/number_field_keys.h"

#include <QAction>
#include <QApplication>
#include <QDoubleSpinBox>
#include <QKeyEvent>
#include <algorithm>

namespace fooball::gui {

namespace {

/// Characters that may be part of a number a field takes ("-1.5e3", "0,5" in some locales).
bool isNumberCharacter(QChar c, bool real) {
  if (c.isDigit() || c == u'-' || c == u'+') return true;
  return real && (c == u'.' || c == u',' || c == u'e' || c == u'E');
}

}  // namespace

bool isBeingEdited(const QDoubleSpinBox& field) {
  return field.cleanText() != field.textFromValue(field.value());
}

NumberFieldKeys::NumberFieldKeys(QWidget& window, QWidget& home)
    : QObject(&window), window_(window), home_(home) {
  qApp->installEventFilter(this);
}

bool NumberFieldKeys::isShortcut(const QKeyEvent& key) const {
  const QKeySequence pressed(key.keyCombination().key() | (key.modifiers() & ~Qt::KeypadModifier));
  const auto actions = window_.findChildren<QAction*>();
  return std::any_of(actions.begin(), actions.end(),
                     [&](const QAction* action) { return action->shortcuts().contains(pressed); });
}

bool NumberFieldKeys::isAppKey(const QAbstractSpinBox& field, const QKeyEvent& key) const {
  const QString text = key.text();
  if (text.size() != 1 || !text.front().isPrint()) return false;
  if (key.modifiers() & ~(Qt::ShiftModifier | Qt::KeypadModifier)) return false;
  if (!isShortcut(key)) return false;
  const auto* real = qobject_cast<const QDoubleSpinBox*>(&field);
  if (!isNumberCharacter(text.front(), real != nullptr)) return true;
  return real == nullptr || !isBeingEdited(*real);
}

bool NumberFieldKeys::eventFilter(QObject* watched, QEvent* event) {
  const QEvent::Type type = event->type();
  if (type != QEvent::ShortcutOverride && type != QEvent::KeyPress && type != QEvent::KeyRelease) {
    return false;
  }
  const auto* field = qobject_cast<QAbstractSpinBox*>(watched);
  if (field == nullptr || !window_.isAncestorOf(field)) return false;
  const auto& key = *static_cast<QKeyEvent*>(event);
  if (type == QEvent::KeyRelease) {
    // The press finished the edit (editingFinished); now the box takes the keyboard back.
    if (key.key() == Qt::Key_Return || key.key() == Qt::Key_Enter) home_.setFocus();
    return false;
  }
  if (!isAppKey(*field, key)) return false;
  // Not accepting the override lets the shortcut have the key; eating the press keeps it out of
  // the field when no shortcut took it ('.' while running: Single step is off).
  event->ignore();
  return true;
}

}  // namespace fooball::gui
