#include "simulation_view.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

#include "charts/chart_panel.h"
#include "disc_rasterizer.h"
#include "fooball/simulation.h"
#include "run_controller.h"

namespace fooball::gui {

namespace {

constexpr int kBoxMargin = 14;                 // px around each box
constexpr QRgb kSurround = 0xff16171c;         // outside the box
constexpr QRgb kWallColour = 0xff6b7385;       // walls that are on; dashed when off
constexpr QRgb kVectorColour = 0xff9be564;     // velocity vectors
constexpr QRgb kAttractorColour = 0xffffd166;  // permanent attractors and the slingshot band
constexpr double kVectorSeconds = 0.25;        // a velocity vector shows 0.25 s of travel
constexpr double kPickSlack = 4.0;             // px beyond a ball's edge that still picks it
constexpr double kMinOutlineRadius = 2.5;      // px: smaller compare-run balls are dots
/// Above this many lines, antialiasing costs more than it shows.
constexpr std::size_t kAntialiasedLineLimit = 2000;
/// Tethers take their ball's colour (as in the original FooBall) up to this many balls.
constexpr std::size_t kColouredTetherLimit = 500;

/// The smallest of 1, 2, 5 × 10^k at or above `value`, so the legend reads a round number and
/// does not flicker from frame to frame.
double roundUp(double value) {
  if (!(value > 0.0)) return 1.0;
  const double decade = std::pow(10.0, std::floor(std::log10(value)));
  for (const double step : {1.0, 2.0, 5.0, 10.0}) {
    if (step * decade >= value) return step * decade;
  }
  return 10.0 * decade;
}

QColor toolColour(MouseMode mode) {
  switch (mode) {
    case MouseMode::Attract:
      return QColor(0x4c, 0xc9, 0xf0);
    case MouseMode::Repel:
      return QColor(0xff, 0x6b, 0x6b);
    case MouseMode::Grab:
      return QColor(0xf0, 0xf0, 0xf0);
    case MouseMode::Slingshot:
      return QColor::fromRgb(kAttractorColour);
  }
  return Qt::white;
}

/// Side by side: the tiles' columns and rows.
struct TileGrid {
  int columns = 1;
  int rows = 1;
};

void drawPill(QPainter& painter, const QRectF& rect) {
  painter.setPen(QPen(QColor(255, 255, 255, 40), 1.0));
  painter.setBrush(QColor(12, 13, 18, 205));
  painter.drawRoundedRect(rect, 6.0, 6.0);
}

}  // namespace

SimulationView::SimulationView(const RunController& runs, QWidget* parent)
    : QWidget(parent), runs_(runs) {
  setAttribute(Qt::WA_OpaquePaintEvent);
  setMouseTracking(true);
  // A click in the box takes the keyboard from a field of the sidebar, so Space and '.' pause
  // and step instead of typing into it.
  setFocusPolicy(Qt::ClickFocus);
  setCursor(Qt::CrossCursor);
  setToolTip(
      tr("Left button: the mouse tool (attract, repel, grab, slingshot).\n"
         "Right button: place a permanent attractor.\n"
         "Paused: click a ball to select it and edit it in the inspector."));
}

void SimulationView::setTemperatureColouring(bool on) {
  temperature_ = on;
  update();
}

void SimulationView::setTethers(bool on) {
  tethers_ = on;
  update();
}

void SimulationView::setVelocityVectors(bool on) {
  velocityVectors_ = on;
  update();
}

void SimulationView::setCentreOfMass(bool on) {
  centreOfMass_ = on;
  update();
}

void SimulationView::setCompareLayout(CompareLayout layout) {
  compareLayout_ = layout;
  update();
}

TileGrid tileGrid(int tiles, QSize area, const Box& box) {
  // The grid whose tiles show the box largest, each keeping the box's aspect ratio. On a tie
  // (a 16:9 box in a 16:9 view fits 1×2 and 2×1 alike) the squarer grid wins: 2 runs 1×2,
  // 3–4 runs 2×2, 5–6 runs 2×3.
  TileGrid best;
  double bestScale = -1.0;
  const int preferred = static_cast<int>(std::ceil(std::sqrt(double(tiles))));
  for (int offset = 0; offset < tiles; ++offset) {
    for (const int columns : {preferred + offset, preferred - offset}) {
      if (columns < 1 || columns > tiles) continue;
      const int rows = (tiles + columns - 1) / columns;
      const double scale = std::min((area.width() / double(columns) - 2 * kBoxMargin) / box.width,
                                    (area.height() / double(rows) - 2 * kBoxMargin) / box.height);
      if (scale > bestScale * (1.0 + 1e-9)) {
        bestScale = scale;
        best = {columns, rows};
      }
    }
  }
  return best;
}

std::vector<SimulationView::Panel> SimulationView::panels() const {
  const Box& box = runs_.run(0).box();
  const int runs = runs_.runCount();
  if (runs == 1 || compareLayout_ == CompareLayout::Overlay) {
    return {{0, runs > 1, ViewTransform(box, rect(), kBoxMargin)}};
  }
  const TileGrid grid = tileGrid(runs, size(), box);
  std::vector<Panel> tiles;
  for (int index = 0; index < runs; ++index) {
    const int column = index % grid.columns;
    const int row = index / grid.columns;
    const int left = width() * column / grid.columns;
    const int top = height() * row / grid.rows;
    const QRect cell(left, top, width() * (column + 1) / grid.columns - left,
                     height() * (row + 1) / grid.rows - top);
    tiles.push_back({index, false, ViewTransform(box, cell, kBoxMargin)});
  }
  return tiles;
}

const SimulationView::Panel* SimulationView::panelAt(QPointF position,
                                                     const std::vector<Panel>& panels) const {
  // The tile whose box is nearest: in the gutters between boxes the tool still has a box.
  const auto distance = [&](const Panel& panel) {
    const QRectF box = panel.transform.boxRect();
    const double dx = std::max({box.left() - position.x(), 0.0, position.x() - box.right()});
    const double dy = std::max({box.top() - position.y(), 0.0, position.y() - box.bottom()});
    return dx * dx + dy * dy;
  };
  return &*std::min_element(panels.begin(), panels.end(), [&](const Panel& a, const Panel& b) {
    return distance(a) < distance(b);
  });
}

ViewTransform SimulationView::transformForRun(int runIndex) const {
  const auto all = panels();
  for (const Panel& panel : all) {
    if (panel.runIndex == runIndex) return panel.transform;
  }
  return all.front().transform;  // overlay: every run in the one box
}

Vec2 SimulationView::toMetres(QPointF position) const {
  const auto all = panels();
  return panelAt(position, all)->transform.toMetres(position);
}

std::optional<std::size_t> SimulationView::ballAt(QPointF position) const {
  const auto all = panels();
  const Panel& panel = *panelAt(position, all);
  const Simulation& run = runs_.run(panel.runIndex);
  const Vec2 point = panel.transform.toMetres(position);
  const double slack = panel.transform.toMetres(kPickSlack);
  std::optional<std::size_t> best;
  double bestDistance = 0.0;
  for (std::size_t i = 0; i < run.ballCount(); ++i) {
    const double distance = length(run.positions()[i] - point);
    if (distance <= run.radii()[i] + slack && (!best || distance < bestDistance)) {
      best = i;
      bestDistance = distance;
    }
  }
  return best;
}

double SimulationView::temperatureTopSpeed() {
  const auto velocities = runs_.run(0).velocities();
  double sumSquares = 0.0;
  for (const Vec2 v : velocities)
    sumSquares += lengthSquared(v);
  const double rms = velocities.empty() ? 0.0 : std::sqrt(sumSquares / double(velocities.size()));
  // Twice the RMS speed: the Maxwell–Boltzmann tail is red, the bulk spans the scale.
  topSpeed_ = roundUp(2.0 * rms);
  return topSpeed_;
}

void SimulationView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), QColor::fromRgb(kSurround));
  const auto all = panels();
  if (temperature_) temperatureTopSpeed();
  for (std::size_t k = 0; k < all.size(); ++k) {
    const Panel& panel = all[k];
    const Simulation& run = runs_.run(panel.runIndex);
    painter.setRenderHint(QPainter::Antialiasing, false);
    paintBalls(painter, panel, k);
    paintBox(painter, panel);
    // Overlays stay inside their box, so side-by-side panels do not draw over each other.
    painter.save();
    painter.setClipRect(panel.transform.boxRect());
    if (velocityVectors_) paintVelocityVectors(painter, panel, run);
    paintTethers(painter, panel, run);
    painter.setRenderHint(QPainter::Antialiasing, true);
    if (centreOfMass_) paintCentreOfMass(painter, panel);
    paintSelection(painter, panel);
    painter.restore();
    painter.setRenderHint(QPainter::Antialiasing, true);
    paintRunLabels(painter, panel);
  }
  const QRect lastBox = all.back().transform.boxRect();
  if (temperature_) paintTemperatureLegend(painter, lastBox);
  if (runs_.paused()) paintPausedBadge(painter, all.front().transform.boxRect().united(lastBox));
}

void SimulationView::paintBalls(QPainter& painter, const Panel& panel, std::size_t panelIndex) {
  const double pixelRatio = devicePixelRatioF();
  const QRect boxRect = panel.transform.boxRect();
  const QSize imageSize(static_cast<int>(std::ceil(boxRect.width() * pixelRatio)),
                        static_cast<int>(std::ceil(boxRect.height() * pixelRatio)));
  if (ballImages_.size() <= panelIndex) ballImages_.resize(panelIndex + 1);
  QImage& image = ballImages_[panelIndex];
  if (image.size() != imageSize) image = QImage(imageSize, QImage::Format_ARGB32_Premultiplied);
  image.setDevicePixelRatio(1.0);
  image.fill(Qt::black);

  rasterizer_.setTarget(image);
  const double scale = panel.transform.scale() * pixelRatio;
  const double boxHeight = runs_.run(panel.runIndex).box().height;
  const auto toImage = [&](Vec2 p) { return QPointF(p.x * scale, (boxHeight - p.y) * scale); };

  const Simulation& run = runs_.run(panel.runIndex);
  const auto positions = run.positions();
  const auto velocities = run.velocities();
  const auto radii = run.radii();
  const auto colours = runs_.group().colours();
  const std::size_t count = std::min(positions.size(), colours.size());
  for (std::size_t i = 0; i < count; ++i) {
    const QRgb colour =
        temperature_ ? palette_.colourAt(length(velocities[i]) / topSpeed_) : QRgb(colours[i]);
    rasterizer_.fillDisc(toImage(positions[i]), radii[i] * scale, colour);
  }
  for (int runIndex = 1; panel.overlay && runIndex < runs_.runCount(); ++runIndex) {
    const Simulation& other = runs_.run(runIndex);
    const QRgb outline = ChartPanel::runColour(runIndex).rgb();
    const auto otherPositions = other.positions();
    const auto otherRadii = other.radii();
    for (std::size_t i = 0; i < otherPositions.size(); ++i) {
      const double radius = otherRadii[i] * scale;
      if (radius < kMinOutlineRadius * pixelRatio) {
        // Too small for a ring to read: a dot half the size, so the filled ball shows around it.
        rasterizer_.fillDisc(toImage(otherPositions[i]), 0.5 * radius, outline);
        continue;
      }
      const double lineWidth = std::clamp(0.25 * radius, 1.0, 2.0) * pixelRatio;
      rasterizer_.strokeCircle(toImage(otherPositions[i]), radius, lineWidth, outline);
    }
  }
  image.setDevicePixelRatio(pixelRatio);
  painter.drawImage(boxRect.topLeft(), image);
}

void SimulationView::paintBox(QPainter& painter, const Panel& panel) const {
  const Walls& walls = runs_.run(panel.runIndex).world().walls;
  const QRectF box = QRectF(panel.transform.boxRect()).adjusted(-1.0, -1.0, 1.0, 1.0);
  const QPen on(QColor::fromRgb(kWallColour), 2.0);
  QPen off(QColor(0x6b, 0x73, 0x85, 150), 1.0, Qt::DashLine);
  painter.setPen(walls.left ? on : off);
  painter.drawLine(box.topLeft(), box.bottomLeft());
  painter.setPen(walls.right ? on : off);
  painter.drawLine(box.topRight(), box.bottomRight());
  painter.setPen(walls.bottom ? on : off);
  painter.drawLine(box.bottomLeft(), box.bottomRight());
  painter.setPen(walls.top ? on : off);
  painter.drawLine(box.topLeft(), box.topRight());
}

void SimulationView::paintVelocityVectors(QPainter& painter, const Panel& panel,
                                          const Simulation& run) {
  const auto positions = run.positions();
  const auto velocities = run.velocities();
  lines_.clear();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    lines_.emplace_back(panel.transform.toPixels(positions[i]),
                        panel.transform.toPixels(positions[i] + kVectorSeconds * velocities[i]));
  }
  painter.setRenderHint(QPainter::Antialiasing, lines_.size() <= kAntialiasedLineLimit);
  painter.setPen(QPen(QColor(0x9b, 0xe5, 0x64, 210), 1.2));
  painter.drawLines(lines_.data(), static_cast<int>(lines_.size()));
}

void SimulationView::paintTethers(QPainter& painter, const Panel& panel, const Simulation& run) {
  const Interactions& tools = run.interactions;
  const ViewTransform& t = panel.transform;
  const auto positions = run.positions();
  const auto colours = runs_.group().colours();
  const bool fewBalls = positions.size() <= kColouredTetherLimit;
  const auto tetherAll = [&](QPointF from, QColor uniform) {
    if (fewBalls && positions.size() <= colours.size()) {
      painter.setRenderHint(QPainter::Antialiasing, true);
      for (std::size_t i = 0; i < positions.size(); ++i) {
        QColor colour = QColor::fromRgb(colours[i]);
        colour.setAlpha(170);
        painter.setPen(QPen(colour, 1.0));
        painter.drawLine(from, t.toPixels(positions[i]));
      }
      return;
    }
    lines_.clear();
    for (const Vec2 p : positions)
      lines_.emplace_back(from, t.toPixels(p));
    painter.setRenderHint(QPainter::Antialiasing, lines_.size() <= kAntialiasedLineLimit);
    painter.setPen(QPen(uniform, 1.0));
    painter.drawLines(lines_.data(), static_cast<int>(lines_.size()));
  };

  for (const Vec2 attractor : tools.attractors()) {
    const QPointF at = t.toPixels(attractor);
    if (tethers_) tetherAll(at, QColor(0xff, 0xd1, 0x66, 28));
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(QPen(QColor::fromRgb(kAttractorColour), 2.0));
    painter.setBrush(Qt::NoBrush);
    painter.drawEllipse(at, 7.0, 7.0);
    painter.drawLine(at - QPointF(3.5, 0), at + QPointF(3.5, 0));
    painter.drawLine(at - QPointF(0, 3.5), at + QPointF(0, 3.5));
  }

  if (!tools.pressed()) return;
  const QPointF cursor = t.toPixels(tools.cursor());
  const QColor colour = toolColour(tools.mode);
  const auto target = tools.target();
  if (tethers_ || tools.mode == MouseMode::Slingshot || tools.mode == MouseMode::Grab) {
    if (target && *target < positions.size()) {
      painter.setRenderHint(QPainter::Antialiasing, true);
      painter.setPen(QPen(colour, 1.5));
      painter.drawLine(cursor, t.toPixels(positions[*target]));
      if (tools.mode == MouseMode::Slingshot) {
        // Where the ball will fly: opposite to the pull.
        const QPointF ball = t.toPixels(positions[*target]);
        const QPointF aim = ball + (ball - cursor);
        painter.setPen(QPen(colour, 1.5, Qt::DashLine));
        painter.drawLine(ball, aim);
      }
    } else if (!target && tools.scope == Scope::All &&
               (tools.mode == MouseMode::Attract || tools.mode == MouseMode::Repel)) {
      QColor uniform = colour;
      uniform.setAlpha(40);
      tetherAll(cursor, uniform);
    }
  }
  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.setPen(QPen(colour, 2.0));
  painter.setBrush(Qt::NoBrush);
  painter.drawEllipse(cursor, 9.0, 9.0);
}

void SimulationView::paintCentreOfMass(QPainter& painter, const Panel& panel) const {
  const auto mark = [&](const Simulation& run, QColor colour) {
    const auto positions = run.positions();
    const auto masses = run.masses();
    double totalMass = 0.0;
    Vec2 weighted;
    for (std::size_t i = 0; i < positions.size(); ++i) {
      weighted += masses[i] * positions[i];
      totalMass += masses[i];
    }
    if (totalMass <= 0.0) return;
    const QPointF at = panel.transform.toPixels(weighted / totalMass);
    painter.setPen(QPen(colour, 2.0));
    painter.setBrush(Qt::NoBrush);
    painter.drawEllipse(at, 6.0, 6.0);
    painter.drawLine(at - QPointF(12, 0), at + QPointF(12, 0));
    painter.drawLine(at - QPointF(0, 12), at + QPointF(0, 12));
  };
  mark(runs_.run(panel.runIndex), Qt::white);
  for (int runIndex = 1; panel.overlay && runIndex < runs_.runCount(); ++runIndex)
    mark(runs_.run(runIndex), ChartPanel::runColour(runIndex));
}

void SimulationView::paintSelection(QPainter& painter, const Panel& panel) const {
  const auto selected = runs_.group().selected();
  if (!selected) return;
  const auto ring = [&](const Simulation& run, QColor colour) {
    if (*selected >= run.ballCount()) return;
    const QPointF at = panel.transform.toPixels(run.positions()[*selected]);
    const double radius = panel.transform.toPixels(run.radii()[*selected]) + 4.0;
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(QColor(0, 0, 0, 180), 4.0));
    painter.drawEllipse(at, radius, radius);
    painter.setPen(QPen(colour, 2.0));
    painter.drawEllipse(at, radius, radius);
    painter.setPen(colour);
    painter.drawText(at + QPointF(radius * 0.75 + 4.0, -radius * 0.75 - 4.0),
                     QStringLiteral("#%1").arg(*selected));
  };
  ring(runs_.run(panel.runIndex), Qt::white);
  for (int runIndex = 1; panel.overlay && runIndex < runs_.runCount(); ++runIndex)
    ring(runs_.run(runIndex), ChartPanel::runColour(runIndex));
}

void SimulationView::paintRunLabels(QPainter& painter, const Panel& panel) const {
  if (!runs_.comparing()) return;
  struct Entry {
    int runIndex;
    QString text;
    bool outline;
  };
  std::vector<Entry> entries;
  if (panel.overlay) {
    entries.push_back({0, tr("%1 — filled").arg(runs_.label(0)), false});
    for (int runIndex = 1; runIndex < runs_.runCount(); ++runIndex)
      entries.push_back({runIndex, tr("%1 — outlines").arg(runs_.label(runIndex)), true});
  } else {
    entries.push_back({panel.runIndex, runs_.label(panel.runIndex), false});
  }
  const QFontMetrics metrics(font());
  int textWidth = 0;
  for (const Entry& entry : entries)
    textWidth = std::max(textWidth, metrics.horizontalAdvance(entry.text));
  const double lineHeight = metrics.height() + 4.0;
  const QRectF pill(panel.transform.boxRect().left() + 10.0, panel.transform.boxRect().top() + 10.0,
                    textWidth + 40.0, lineHeight * double(entries.size()) + 10.0);
  drawPill(painter, pill);
  double y = pill.top() + 5.0;
  for (const Entry& entry : entries) {
    const QColor colour = ChartPanel::runColour(entry.runIndex);
    const QPointF swatch(pill.left() + 15.0, y + lineHeight / 2.0);
    if (entry.outline) {
      painter.setPen(QPen(colour, 2.0));
      painter.setBrush(Qt::NoBrush);
    } else {
      painter.setPen(Qt::NoPen);
      painter.setBrush(colour);
    }
    painter.drawEllipse(swatch, 5.5, 5.5);
    painter.setPen(QColor(0xe8, 0xea, 0xf0));
    painter.drawText(QRectF(pill.left() + 28.0, y, textWidth + 8.0, lineHeight),
                     Qt::AlignVCenter | Qt::AlignLeft, entry.text);
    y += lineHeight;
  }
}

void SimulationView::paintTemperatureLegend(QPainter& painter, const QRect& box) const {
  const QFontMetrics metrics(font());
  const QString top = tr("%1 m/s").arg(topSpeed_, 0, 'g', 3);
  const double barWidth = 150.0;
  const QRectF pill(box.left() + 10.0, box.bottom() - 10.0 - (2.0 * metrics.height() + 22.0),
                    barWidth + 24.0, 2.0 * metrics.height() + 22.0);
  drawPill(painter, pill);
  painter.setPen(QColor(0xe8, 0xea, 0xf0));
  painter.drawText(QPointF(pill.left() + 12.0, pill.top() + 6.0 + metrics.ascent()), tr("speed"));
  const QRectF bar(pill.left() + 12.0, pill.top() + 10.0 + metrics.height(), barWidth, 8.0);
  painter.setPen(Qt::NoPen);
  painter.setBrush(palette_.gradient(bar.topLeft(), bar.topRight()));
  painter.drawRoundedRect(bar, 3.0, 3.0);
  painter.setPen(QColor(0xb8, 0xbc, 0xc8));
  const double labelsY = bar.bottom() + 3.0 + metrics.ascent();
  painter.drawText(QPointF(bar.left(), labelsY), QStringLiteral("0"));
  painter.drawText(QPointF(bar.right() - metrics.horizontalAdvance(top), labelsY), top);
}

void SimulationView::paintPausedBadge(QPainter& painter, const QRect& box) const {
  const QString text = tr("Paused — click a ball to select it, “.” steps once");
  const QFontMetrics metrics(font());
  const double width = metrics.horizontalAdvance(text) + 28.0;
  const QRectF pill(box.center().x() - width / 2.0, box.top() + 10.0, width,
                    metrics.height() + 10.0);
  drawPill(painter, pill);
  painter.setPen(QColor(0xff, 0xd1, 0x66));
  painter.drawText(pill, Qt::AlignCenter, text);
}

void SimulationView::mousePressEvent(QMouseEvent* event) {
  const Vec2 point = toMetres(event->position());
  if (event->button() == Qt::RightButton) {
    emit attractorPlaced(point);
  } else if (event->button() == Qt::LeftButton) {
    if (runs_.paused()) {
      emit ballClicked(ballAt(event->position()));
    } else {
      toolHeld_ = true;
      emit toolPressed(point);
    }
  }
  update();
}

void SimulationView::mouseMoveEvent(QMouseEvent* event) {
  const Vec2 point = toMetres(event->position());
  if (toolHeld_) emit toolMoved(point);
  emit cursorMoved(point);
}

void SimulationView::mouseReleaseEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton && toolHeld_) {
    toolHeld_ = false;
    emit toolReleased(toMetres(event->position()));
    update();
  }
}

}  // namespace fooball::gui
