#pragma once

#include <QIcon>

class QPainter;
class QRectF;

namespace fooball::gui {

/// The app's check box, drawn in `box`: a light outline when off, a filled box with a tick when
/// on (a bar for partly checked); dimmer when disabled. Light enough on the dark theme to read,
/// where the Fusion style's own outline is darker than the window behind it.
void paintCheckBox(QPainter& painter, const QRectF& box, Qt::CheckState state, bool enabled);

/// The round kind, for radio buttons: an outlined circle, a dot inside when on.
void paintRadioButton(QPainter& painter, const QRectF& box, bool on, bool enabled);

/// paintCheckBox as an icon, for the checkable actions of a text tool bar: ticked when on
/// (QIcon::On), empty when off, so an option that is off still reads as a switch and not as
/// plain text. Drawn at 16 px and twice that for high-density screens.
QIcon toggleIcon();

}  // namespace fooball::gui
