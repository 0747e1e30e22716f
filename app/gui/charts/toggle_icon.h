#pragma once

#include <QIcon>

namespace fooball::gui {

/// A check box as an icon, for the checkable actions of a text tool bar: a ticked box when on
/// (QIcon::On), an empty one when off, so an option that is off still reads as a switch and not
/// as plain text. Drawn at 16 px and twice that for high-density screens.
QIcon toggleIcon();

}  // namespace fooball::gui
