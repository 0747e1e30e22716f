#pragma once

class QWidget;

namespace fooball::gui {

/// Help → About FooBall.
void showAbout(QWidget* parent);
/// Help → Mouse and keys: every mouse action and shortcut on one page.
void showMouseAndKeys(QWidget* parent);

}  // namespace fooball::gui
