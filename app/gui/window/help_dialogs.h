#pragma once

class QWidget;

namespace fooball::gui {

/// Help → About FooBall.
void showAbout(QWidget* parent);
/// Help → Mouse and keys: every mouse action and shortcut on one page.
void showMouseAndKeys(QWidget* parent);
/// Help → Reading the charts: what each chart shows, why the residual is the method's own
/// error, compare mode and the chaos baseline, and the methods (from the registry).
void showReadingTheCharts(QWidget* parent);

}  // namespace fooball::gui
