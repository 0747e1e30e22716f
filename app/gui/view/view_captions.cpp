#include <QFontMetrics>
#include <algorithm>

#include "run/run_controller.h"
#include "view/caption_style.h"
#include "view/simulation_view.h"
#include "widgets/number_format.h"

// SimulationView's captions: laid out in rows above the boxes (and, side by side, a label above
// each tile's box), which also places the boxes.

namespace fooball::gui {

using namespace caption_style;

QString SimulationView::collisionsText(int runIndex) const {
  const BackendCounters counters = runs_.run(runIndex).counters();
  return tr("%1 ball–ball + %2 wall = %3 collisions")
      .arg(formatCount(counters.ballCollisions), formatCount(counters.wallCollisions),
           formatCount(counters.ballCollisions + counters.wallCollisions));
}

QRect SimulationView::lookForCloseButton() const {
  for (const Caption& caption : captions()) {
    if (caption.kind == Caption::Kind::LookFor)
      return closeButtonOf(caption.rect, QFontMetrics(font()).height() + 2 * kPillPadding);
  }
  return {};
}

SimulationView::Layout SimulationView::layout() const {
  // The captions go in rows above the boxes, never on them: a legend or a hint on top of the
  // balls hides what they show. The Paused hint's room is kept while running too, so pausing
  // does not move the box.
  const QFontMetrics metrics(font());
  const int pillHeight = metrics.height() + 2 * kPillPadding;
  const auto pillSize = [&](const QString& text, int extra) {
    // One pixel more than the text's advance: eliding rounds the width down.
    return QSize(metrics.horizontalAdvance(text) + 1 + 2 * kPillPadding + extra, pillHeight);
  };
  const int runs = runs_.runCount();
  const bool overlay = runs == 1 || compareLayout_ == CompareLayout::Overlay;
  Layout result;
  std::vector<QSize> leading;
  // The preset's caption first, as wide as the view so that it has a row of its own, its text
  // wrapped beside an accent bar and the close button.
  if (lookForShown_ && !lookFor_.isEmpty()) {
    const int rowWidth = std::max(width() - 2 * kCaptionGap, 1);
    const int textWidth = std::max(rowWidth - 2 * kPillPadding - kAccentWidth - pillHeight, 1);
    const QRect text =
        metrics.boundingRect(QRect(0, 0, textWidth, QWIDGETSIZE_MAX), Qt::TextWordWrap, lookFor_);
    result.captions.push_back({Caption::Kind::LookFor, 0, lookFor_, {}});
    leading.emplace_back(rowWidth, std::max(text.height() + 2 * kPillPadding, pillHeight));
  }
  // A count the caption promises, per run; sized for three-digit counts, so the pills do not
  // grow (and move the box) as the count climbs.
  for (int runIndex = 0; countsCollisions_ && runIndex < runs; ++runIndex) {
    const QString text = collisionsText(runIndex);
    const int swatch = runs > 1 ? kSwatchWidth : 0;
    const QSize room = pillSize(tr("%1 ball–ball + %1 wall = %1 collisions").arg(999), swatch);
    result.captions.push_back({Caption::Kind::Collisions, runIndex, text, {}});
    leading.push_back(room.expandedTo(pillSize(text, swatch)));
  }
  // The legends from the left (the runs' colours, then the speed scale), the hint on the right.
  if (runs > 1 && overlay) {
    // The swatch says filled (run 0) or outlined (the others), as the balls are drawn.
    for (int runIndex = 0; runIndex < runs; ++runIndex) {
      result.captions.push_back({Caption::Kind::RunEntry, runIndex, runs_.label(runIndex), {}});
      leading.push_back(pillSize(runs_.label(runIndex), kSwatchWidth));
    }
  }
  if (temperature_) {
    const QString text = tr("speed 0 … %1 m/s").arg(topSpeed_, 0, 'g', 3);
    result.captions.push_back({Caption::Kind::Temperature, 0, text, {}});
    leading.push_back(pillSize(text, kTemperatureBarWidth));
  }
  Caption paused{Caption::Kind::Paused, 0, pausedText(), {}};
  const CaptionRows rows =
      layoutCaptionRows(rect(), leading, {pillSize(paused.text, 0)}, kCaptionGap);
  for (std::size_t i = 0; i < leading.size(); ++i)
    result.captions[i].rect = rows.leading[i];
  paused.rect = rows.trailing.front();
  result.captions.push_back(paused);

  // Below the rows; the boxes' own margin is the gap under the last one.
  const QRect area = rect().adjusted(0, std::max(0, rows.height - kBoxMargin + kCaptionGap), 0, 0);
  const Box& box = runs_.run(0).box();
  if (overlay) {
    result.panels.push_back({0, runs > 1, ViewTransform(box, area, kBoxMargin)});
    return result;
  }
  // Side by side: each tile's run named on a line above its box.
  const TileGrid grid = tileGrid(runs, area.size() - QSize(0, pillHeight), box, kBoxMargin);
  for (int index = 0; index < runs; ++index) {
    const int column = index % grid.columns;
    const int row = index / grid.columns;
    const int left = area.left() + area.width() * column / grid.columns;
    const int top = area.top() + area.height() * row / grid.rows;
    const QRect cell(left, top, area.left() + area.width() * (column + 1) / grid.columns - left,
                     area.top() + area.height() * (row + 1) / grid.rows - top);
    const ViewTransform transform(box, cell.adjusted(0, pillHeight, 0, 0), kBoxMargin);
    result.panels.push_back({index, false, transform});
    const QRect boxRect = transform.boxRect();
    const QSize label = pillSize(runs_.label(index), kSwatchWidth);
    result.captions.push_back({Caption::Kind::TileLabel, index, runs_.label(index),
                               QRect(boxRect.left(), boxRect.top() - kCaptionGap - pillHeight,
                                     std::min(label.width(), boxRect.width()), pillHeight)});
  }
  return result;
}

std::vector<SimulationView::Panel> SimulationView::panels() const {
  return layout().panels;
}

std::vector<SimulationView::Caption> SimulationView::captions() const {
  std::vector<Caption> shown = layout().captions;
  if (!runs_.paused()) {
    std::erase_if(shown,
                  [](const Caption& caption) { return caption.kind == Caption::Kind::Paused; });
  }
  return shown;
}

QString SimulationView::pausedText() const {
  return tr("Paused: click a ball to select it, “.” steps");
}

}  // namespace fooball::gui
