#pragma once

#include <QString>

class QWidget;

namespace fooball::gui {

/// Writes `chartArea` (the run legend and the charts, laid out) as a PNG at twice the screen's
/// pixels, under `caption` (the scene and the runs, wrapped at the image's width; also stored as
/// the PNG's "Description" text), so the image explains itself when pasted elsewhere. False when
/// the file was not written.
bool writeChartPng(const QString& path, QWidget& chartArea, const QString& caption);

}  // namespace fooball::gui
