#pragma once

#include <QColor>
#include <QString>
#include <filesystem>
#include <string_view>
#include <vector>

class QChart;

namespace fooball::plots {

/// The colour each backend has in every chart: the registry's order, FooBall's amber first.
QColor backendColor(std::string_view backend);

/// Renders `charts` side by side, each `chartWidth` × `height` pixels, under `title`, into a PNG
/// at `path`. Takes ownership of the charts. Throws std::runtime_error naming the path when the
/// file cannot be written.
void saveCharts(std::vector<QChart*> charts, const QString& title, int chartWidth, int height,
                const std::filesystem::path& path);

}  // namespace fooball::plots
