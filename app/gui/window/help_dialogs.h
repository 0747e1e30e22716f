#pragma once

#include <QString>

class QMenuBar;
class QWidget;

namespace fooball::gui {

/// The file of the docs named `name` ("accuracy.md"): the installed copy
/// (share/doc/fooball, beside the installed bin/), or, run from the build tree, the source
/// tree's docs/.
QString docFile(const QString& name);

/// Help → About FooBall.
void showAbout(QWidget* parent);
/// Help → Mouse and keys: every mouse action, and every shortcut as the actions of `menus` have
/// it, so the page cannot go stale.
QString mouseAndKeysText(const QMenuBar& menus);
void showMouseAndKeys(QWidget* parent, const QMenuBar& menus);
/// Help → Reading the charts: what each chart shows, why the residual is the method's own
/// error, compare mode and the chaos baseline, and the methods (from the registry), with links
/// to the docs.
QString readingTheChartsText();
void showReadingTheCharts(QWidget* parent);

}  // namespace fooball::gui
