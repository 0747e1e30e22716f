#pragma once

#include <QPalette>

class QApplication;
class QChart;

namespace fooball::gui {

/// The one look of the app: the Fusion style (it draws every widget from the palette, so menus,
/// docks, dialogs, file dialogs and tooltips all follow it; its check boxes and radio buttons
/// replaced by ones that show on a dark window) with a dark palette close to the box's and the
/// charts' near-black, text light enough to read on it.
QPalette darkPalette();

/// Sets that style and darkPalette() on `app`: once, at startup, before any window exists.
void applyDarkTheme(QApplication& app);

/// A chart the app shares with fooball-cli (light, as the CLI draws it for pages) in the app's
/// dark theme; the series keep their colours.
void styleChartDark(QChart& chart);

/// WCAG's contrast ratio of two colours, 1 (the same) to 21 (black on white): body text needs
/// at least 4.5.
double contrastRatio(const QColor& a, const QColor& b);

}  // namespace fooball::gui
