#pragma once

#include <QString>
#include <filesystem>
#include <vector>

class QAbstractAxis;
class QAbstractSeries;
class QChart;
class QLogValueAxis;

namespace fooball::plots {

/// The powers of ten just below and just above a positive value.
double decadeBelow(double value);
double decadeAbove(double value);

/// A log axis over whole decades around [low, high] (at least one decade, and up to 1e-11 at
/// least, below which Qt draws no labels), labelled at 1, 10, 100, … or, over more than six
/// decades, every k-th decade so that at most six intervals are labelled; `labelFormat` is
/// printf-style, e.g. "%g" or "%.0e".
QLogValueAxis* decadeAxis(const QString& title, double low, double high, const char* labelFormat);

/// Adds `series` to `chart` on the axes `x` and `y`; with `inLegend` false it has no legend entry
/// (a decoration, e.g. a Pareto front drawn over its points).
void addSeries(QChart* chart, QAbstractSeries* series, QAbstractAxis* x, QAbstractAxis* y,
               bool inLegend);

/// Renders `charts` side by side, each `chartWidth` × `height` pixels, under `title`, into a PNG
/// at `path`. Takes ownership of the charts. Throws std::runtime_error naming the path when the
/// file cannot be written.
void saveCharts(std::vector<QChart*> charts, const QString& title, int chartWidth, int height,
                const std::filesystem::path& path);

}  // namespace fooball::plots
