#pragma once

#include <QImage>
#include <QSize>

class QWidget;

namespace fooball::gui {

class ChartPanel;
class FrameLoop;
class RunController;
class SimulationView;

/// What a recording draws and drives: the window's view, its chart panel in the charts' dock, its
/// frame loop and its runs (not the window itself).
struct RecordingTarget {
  SimulationView& view;
  ChartPanel& charts;
  QWidget& chartsDock;
  FrameLoop& frames;
  const RunController& runs;
};

/// What a recording shows.
enum class RecordArea {
  Box,           ///< the simulation view: the box(es), the legend row and the run labels
  BoxAndCharts,  ///< the view above the chart panel, as they stand in the window
};

/// The picture a recording takes each frame: the window's view (and chart panel) drawn into an
/// image of the video's size. What is shown on screen is drawn again at the video's scale (text
/// and lines sharp at any size, the balls' image scaled), centred on black where the shapes
/// differ; at the size shown it is the screen's picture pixel for pixel.
class RecordingFrameSource {
 public:
  RecordingFrameSource(const RecordingTarget& target, RecordArea area, QSize videoSize);

  /// px: the area as it stands in the window now (the charts only while their dock is shown).
  static QSize shownSize(const RecordingTarget& target, RecordArea area);

  /// Draws the area now; the image (QImage::Format_RGB888, videoSize) stays valid until the next
  /// call.
  const QImage& grab();
  const QImage& image() const { return image_; }

 private:
  RecordingTarget target_;
  RecordArea area_;
  QImage canvas_;  ///< Format_RGB32: what QPainter draws fastest
  QImage image_;
};

}  // namespace fooball::gui
