#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

#include "fooball/drifted_positions.h"
#include "fooball/simulation.h"
#include "run/run_controller.h"
#include "run_palette.h"
#include "view/caption_style.h"
#include "view/simulation_view.h"

// SimulationView's painting: the balls into an image per box, then the walls, vectors, tethers,
// centre of mass, selection and captions on top.

namespace fooball::gui {

using namespace caption_style;

namespace {

constexpr QRgb kSurround = 0xff16171c;         // outside the box
constexpr QRgb kWallColour = 0xff6b7385;       // walls that are on; dashed when off
constexpr QRgb kVectorColour = 0xff9be564;     // velocity vectors
constexpr double kTargetRingGap = 4.0;         // px between a tool's target ball and its ring
constexpr QRgb kAttractorColour = 0xffffd166;  // permanent attractors and the slingshot band
constexpr double kVectorSeconds = 0.25;        // a velocity vector shows 0.25 s of travel
/// Arrowheads: a third of the vector, between these lengths (px), so they read on long vectors
/// without swamping a slow or small ball; none on vectors too short to point anywhere.
constexpr double kArrowheadMin = 3.0;
constexpr double kArrowheadMax = 9.0;
constexpr double kArrowheadHalfAngle = 0.45;  // rad, about 26°
constexpr double kMinOutlineRadius = 2.5;     // px: smaller compare-run balls are dots
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

void drawPill(QPainter& painter, const QRectF& rect) {
  painter.setPen(QPen(QColor(255, 255, 255, 40), 1.0));
  painter.setBrush(QColor(12, 13, 18, 205));
  painter.drawRoundedRect(rect, 6.0, 6.0);
}

}  // namespace

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

void SimulationView::driftRuns() {
  // Every run is drawn the same time ahead: they are in lockstep, so their drawn states stay
  // comparable. The selection, vectors, tethers and centre of mass are drawn from these too,
  // so they move with the balls.
  const double ahead = runs_.drawAhead();
  drawn_.resize(std::size_t(runs_.runCount()));
  for (int runIndex = 0; runIndex < runs_.runCount(); ++runIndex)
    driftedPositions(runs_.run(runIndex), ahead, drawn_[std::size_t(runIndex)]);
}

void SimulationView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), QColor::fromRgb(kSurround));
  const auto all = panels();
  if (temperature_) temperatureTopSpeed();
  driftRuns();
  for (std::size_t k = 0; k < all.size(); ++k) {
    const Panel& panel = all[k];
    painter.setRenderHint(QPainter::Antialiasing, false);
    paintBalls(painter, panel, k);
    paintBox(painter, panel);
    // Overlays stay inside their box, so side-by-side panels do not draw over each other.
    painter.save();
    painter.setClipRect(panel.transform.boxRect());
    if (velocityVectors_) paintVelocityVectors(painter, panel);
    paintTethers(painter, panel);
    painter.setRenderHint(QPainter::Antialiasing, true);
    if (centreOfMass_) paintCentreOfMass(painter, panel);
    paintSelection(painter, panel);
    painter.restore();
  }
  painter.setRenderHint(QPainter::Antialiasing, true);
  paintCaptions(painter, captions());
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
  splat_.begin(imageSize);
  // A ball narrower than a pixel is density, not a disc: as it looks, for a fraction of the cost.
  const auto drawDisc = [&](QPointF centre, double radius, QRgb colour) {
    if (radius < DensitySplat::kMaxRadius) {
      splat_.add(centre, radius, colour);
    } else {
      rasterizer_.fillDisc(centre, radius, colour);
    }
  };
  const double scale = panel.transform.scale() * pixelRatio;
  const double boxHeight = runs_.run(panel.runIndex).box().height;
  const auto toImage = [&](Vec2 p) { return QPointF(p.x * scale, (boxHeight - p.y) * scale); };

  const Simulation& run = runs_.run(panel.runIndex);
  const auto positions = drawnPositions(panel.runIndex);
  const auto velocities = run.velocities();
  const auto radii = run.radii();
  const auto colours = runs_.group().colours();
  const std::size_t count = std::min(positions.size(), colours.size());
  for (std::size_t i = 0; i < count; ++i) {
    const QRgb colour =
        temperature_ ? palette_.colourAt(length(velocities[i]) / topSpeed_) : QRgb(colours[i]);
    drawDisc(toImage(positions[i]), radii[i] * scale, colour);
  }
  for (int runIndex = 1; panel.overlay && runIndex < runs_.runCount(); ++runIndex) {
    const Simulation& other = runs_.run(runIndex);
    const QRgb outline = colours::runColour(runIndex).rgb();
    const auto otherPositions = drawnPositions(runIndex);
    const auto otherRadii = other.radii();
    for (std::size_t i = 0; i < otherPositions.size(); ++i) {
      const double radius = otherRadii[i] * scale;
      if (radius < kMinOutlineRadius * pixelRatio) {
        // Too small for a ring to read: a dot half the size, so the filled ball shows around it.
        drawDisc(toImage(otherPositions[i]), 0.5 * radius, outline);
        continue;
      }
      const double lineWidth = std::clamp(0.25 * radius, 1.0, 2.0) * pixelRatio;
      rasterizer_.strokeCircle(toImage(otherPositions[i]), radius, lineWidth, outline);
    }
  }
  splat_.composeOnto(image);
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

void SimulationView::paintVelocityVectors(QPainter& painter, const Panel& panel) {
  const auto positions = drawnPositions(panel.runIndex);
  const auto velocities = runs_.run(panel.runIndex).velocities();
  lines_.clear();
  const double cosine = std::cos(kArrowheadHalfAngle);
  const double sine = std::sin(kArrowheadHalfAngle);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const QPointF tail = panel.transform.toPixels(positions[i]);
    const QPointF tip = panel.transform.toPixels(positions[i] + kVectorSeconds * velocities[i]);
    lines_.emplace_back(tail, tip);
    // The head's two barbs: the shaft's direction turned back by ± the half angle.
    const QPointF shaft = tip - tail;
    const double length = std::hypot(shaft.x(), shaft.y());
    if (length < kArrowheadMin) continue;
    const double head = std::clamp(length / 3.0, kArrowheadMin, kArrowheadMax);
    const QPointF back = -shaft * (head / length);
    lines_.emplace_back(tip, tip + QPointF(back.x() * cosine - back.y() * sine,
                                           back.x() * sine + back.y() * cosine));
    lines_.emplace_back(tip, tip + QPointF(back.x() * cosine + back.y() * sine,
                                           -back.x() * sine + back.y() * cosine));
  }
  painter.setRenderHint(QPainter::Antialiasing, lines_.size() <= kAntialiasedLineLimit);
  painter.setPen(QPen(QColor(0x9b, 0xe5, 0x64, 210), 1.2));
  painter.drawLines(lines_.data(), static_cast<int>(lines_.size()));
}

void SimulationView::paintTethers(QPainter& painter, const Panel& panel) {
  const Interactions& tools = runs_.run(panel.runIndex).interactions;
  const ViewTransform& t = panel.transform;
  const auto positions = drawnPositions(panel.runIndex);
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
      // The ball the tool took at the press (Interactions::press), ringed so it is obvious.
      const double ring = t.toPixels(runs_.run(panel.runIndex).radii()[*target]) + kTargetRingGap;
      painter.setPen(QPen(colour, 2.0));
      painter.setBrush(Qt::NoBrush);
      painter.drawEllipse(t.toPixels(positions[*target]), ring, ring);
      painter.setPen(QPen(colour, 1.5));
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
  const auto mark = [&](int runIndex, QColor colour) {
    const auto positions = drawnPositions(runIndex);
    const auto masses = runs_.run(runIndex).masses();
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
  mark(panel.runIndex, Qt::white);
  for (int runIndex = 1; panel.overlay && runIndex < runs_.runCount(); ++runIndex)
    mark(runIndex, colours::runColour(runIndex));
}

void SimulationView::paintSelection(QPainter& painter, const Panel& panel) const {
  const auto selected = runs_.group().selected();
  if (!selected) return;
  const auto ring = [&](int runIndex, QColor colour) {
    const Simulation& run = runs_.run(runIndex);
    if (*selected >= run.ballCount()) return;
    const QPointF at = panel.transform.toPixels(drawnPositions(runIndex)[*selected]);
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
  ring(panel.runIndex, Qt::white);
  for (int runIndex = 1; panel.overlay && runIndex < runs_.runCount(); ++runIndex)
    ring(runIndex, colours::runColour(runIndex));
}

void SimulationView::paintCaptions(QPainter& painter, const std::vector<Caption>& captions) const {
  const QFontMetrics metrics(font());
  for (const Caption& caption : captions) {
    const QRectF pill(caption.rect);
    drawPill(painter, pill);
    const QRectF inner = pill.adjusted(kPillPadding, 0, -kPillPadding, 0);
    switch (caption.kind) {
      case Caption::Kind::RunEntry:
      case Caption::Kind::TileLabel: {
        const QColor colour = colours::runColour(caption.runIndex);
        const QPointF swatch(inner.left() + kSwatchWidth / 2.0 - 3.0, pill.center().y());
        const bool outline = caption.kind == Caption::Kind::RunEntry && caption.runIndex > 0;
        painter.setPen(outline ? QPen(colour, 2.0) : QPen(Qt::NoPen));
        painter.setBrush(outline ? QBrush(Qt::NoBrush) : QBrush(colour));
        painter.drawEllipse(swatch, 5.5, 5.5);
        painter.setPen(QColor(0xe8, 0xea, 0xf0));
        const QRectF text = inner.adjusted(kSwatchWidth, 0, 0, 0);
        painter.drawText(text, Qt::AlignVCenter | Qt::AlignLeft,
                         metrics.elidedText(caption.text, Qt::ElideMiddle, int(text.width())));
        break;
      }
      case Caption::Kind::Temperature: {
        // "speed 0 [gradient] 20 m/s": the ends of the colour scale, in one line.
        const QString low = tr("speed 0");
        const QString high = tr("%1 m/s").arg(topSpeed_, 0, 'g', 3);
        painter.setPen(QColor(0xe8, 0xea, 0xf0));
        painter.drawText(inner, Qt::AlignVCenter | Qt::AlignLeft, low);
        painter.drawText(inner, Qt::AlignVCenter | Qt::AlignRight, high);
        const double barLeft = inner.left() + metrics.horizontalAdvance(low) + 6.0;
        const double barRight = inner.right() - metrics.horizontalAdvance(high) - 6.0;
        const QRectF bar(barLeft, pill.center().y() - 4.0, std::max(barRight - barLeft, 1.0), 8.0);
        painter.setPen(Qt::NoPen);
        painter.setBrush(palette_.gradient(bar.topLeft(), bar.topRight()));
        painter.drawRoundedRect(bar, 3.0, 3.0);
        break;
      }
      case Caption::Kind::LookFor: {
        // An accent bar, the text wrapped beside it, and the close button's cross.
        painter.setPen(Qt::NoPen);
        painter.setBrush(QColor::fromRgb(kAttractorColour));
        painter.drawRoundedRect(QRectF(inner.left() + 1.0, pill.top() + kPillPadding + 1.0, 3.0,
                                       pill.height() - 2.0 * kPillPadding - 2.0),
                                1.5, 1.5);
        const QRectF close = closeButtonOf(caption.rect, metrics.height() + 2 * kPillPadding);
        painter.setPen(QColor(0xe8, 0xea, 0xf0));
        painter.drawText(inner.adjusted(kAccentWidth, kPillPadding, -close.width(), -kPillPadding),
                         Qt::AlignVCenter | Qt::AlignLeft | Qt::TextWordWrap, caption.text);
        const double arm = 0.18 * close.height();
        painter.setPen(QPen(QColor(0xb0, 0xb6, 0xc4), 1.6, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(close.center() + QPointF(-arm, -arm), close.center() + QPointF(arm, arm));
        painter.drawLine(close.center() + QPointF(-arm, arm), close.center() + QPointF(arm, -arm));
        break;
      }
      case Caption::Kind::Collisions: {
        QRectF text = inner;
        if (runs_.runCount() > 1) {
          // The run's colour, filled or outlined as its balls are drawn.
          const QColor colour = colours::runColour(caption.runIndex);
          const QPointF swatch(inner.left() + kSwatchWidth / 2.0 - 3.0, pill.center().y());
          painter.setPen(caption.runIndex > 0 ? QPen(colour, 2.0) : QPen(Qt::NoPen));
          painter.setBrush(caption.runIndex > 0 ? QBrush(Qt::NoBrush) : QBrush(colour));
          painter.drawEllipse(swatch, 5.5, 5.5);
          text.adjust(kSwatchWidth, 0, 0, 0);
        }
        painter.setPen(QColor::fromRgb(kAttractorColour));
        painter.drawText(text, Qt::AlignVCenter | Qt::AlignLeft,
                         metrics.elidedText(caption.text, Qt::ElideRight, int(text.width())));
        break;
      }
      case Caption::Kind::Paused:
        painter.setPen(QColor(0xff, 0xd1, 0x66));
        painter.drawText(pill, Qt::AlignCenter,
                         metrics.elidedText(caption.text, Qt::ElideRight, int(inner.width())));
        break;
    }
  }
}

}  // namespace fooball::gui
