#pragma once

#include <QString>

class QLabel;

/// What the readouts share: their figures' text, their grids' labels and their refresh rate.
namespace fooball::gui {

/// ms between refreshes of the readouts that poll the runs (the status bar, the timeline): four
/// a second, as fast as a figure can be read.
inline constexpr int kReadoutRefreshMs = 250;

/// A measured figure as the readouts show it (text::figureText: "0.0123", "—" for none).
QString figure(double value);
/// The text of a cell without a figure (yet): "—".
QString noFigure();
/// A new label of a readout's grid: `text`, styled by its `role` property (the readout's style
/// sheet: "caption", "value", …), with `toolTip`.
QLabel* readoutCell(const QString& text, const char* role, const QString& toolTip = {});

}  // namespace fooball::gui
