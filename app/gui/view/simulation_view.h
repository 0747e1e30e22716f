#pragma once

#include <QImage>
#include <QLineF>
#include <QWidget>
#include <optional>
#include <span>
#include <vector>

#include "fooball/vec2.h"
#include "view/density_splat.h"
#include "view/disc_rasterizer.h"
#include "view/temperature_palette.h"
#include "view/view_layout.h"
#include "view/view_transform.h"

namespace fooball {
class Simulation;
struct Preset;
}  // namespace fooball

namespace fooball::gui {

class RunController;

/// How compare mode shows its runs.
enum class CompareLayout {
  Overlay,     ///< one box: run 0 filled, every other run as outlines in its colour on top
  SideBySide,  ///< a grid of labelled boxes (2 runs 1×2, 3–4 runs 2×2, …), each run filled
};

/// The black box of balls, painted from the runs' current state, and the mouse tools on it.
/// Balls are rasterised into an image (DiscRasterizer); tethers, vectors and labels are
/// painted on top with QPainter (view_painting.cpp). The captions' layout, which also places the
/// boxes, is in view_captions.cpp; which box, point and ball a pixel is, in view_hit_testing.cpp.
class SimulationView : public QWidget {
  Q_OBJECT

 public:
  explicit SimulationView(const RunController& runs, QWidget* parent = nullptr);

  QSize sizeHint() const override { return {960, 540}; }
  QSize minimumSizeHint() const override { return {240, 160}; }

  /// The mapping of the box that shows run `runIndex` (side by side: each run has its own).
  ViewTransform transformForRun(int runIndex) const;

  /// A legend entry or a hint, drawn in the rows above the boxes (or, side by side, on the line
  /// above a tile's box): never on the balls.
  struct Caption {
    enum class Kind {
      RunEntry,     ///< overlay: a run's colour, filled (run 0) or outlined
      TileLabel,    ///< side by side: the run a box shows
      Temperature,  ///< the speed colour scale
      Paused,       ///< what a click does while paused
      LookFor,      ///< the preset's "what to look for", wrapped, with a close button
      Collisions,   ///< a run's collision count, for a preset whose promise is a count
    };
    Kind kind;
    int runIndex = 0;
    QString text;
    QRect rect;  ///< widget px
  };
  /// The captions drawn now (the Paused hint only while paused).
  std::vector<Caption> captions() const;

  /// Where the last paint drew run `runIndex`'s balls (m): its stepped state carried ahead by
  /// the simulated time it does not hold yet (RunController::drawAhead, driftedPositions), so
  /// slow motion moves every frame; exactly the stepped state while paused.
  std::span<const Vec2> drawnPositions(int runIndex) const {
    return drawn_.at(std::size_t(runIndex));
  }

  bool temperatureColouring() const { return temperature_; }
  bool tethers() const { return tethers_; }
  bool velocityVectors() const { return velocityVectors_; }
  bool centreOfMass() const { return centreOfMass_; }
  CompareLayout compareLayout() const { return compareLayout_; }
  bool lookForShown() const { return lookForShown_; }

  /// The loaded preset, whose "what to look for" caption (and, when its promise is a count, each
  /// run's collisions) the view shows above the box; nullptr for a scene from a file.
  void setPreset(const Preset* preset);
  /// The caption's close button, in widget px (empty while no caption is shown).
  QRect lookForCloseButton() const;

 public slots:
  void setTemperatureColouring(bool on);
  void setTethers(bool on);
  void setVelocityVectors(bool on);
  void setCentreOfMass(bool on);
  void setCompareLayout(CompareLayout layout);
  /// Shows or hides the preset's caption (View → What to look for).
  void setLookForShown(bool on);

 signals:
  /// The caption's close button was clicked.
  void lookForClosed();
  /// Left button while running: the mouse tool (positions in m).
  void toolPressed(Vec2 point);
  void toolMoved(Vec2 point);
  void toolReleased(Vec2 point);
  /// Right button: a permanent attractor.
  void attractorPlaced(Vec2 point);
  /// Left click while paused: the ball under the cursor, or none.
  void ballClicked(std::optional<std::size_t> index);
  /// Where the cursor is over the box (m), for the status bar.
  void cursorMoved(Vec2 point);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;

 private:
  struct Panel {
    int runIndex;  ///< the run drawn filled
    bool overlay;  ///< the other runs are drawn as outlines on top
    ViewTransform transform;
  };
  struct Layout {
    std::vector<Panel> panels;
    std::vector<Caption> captions;  ///< the Paused hint's included: its room is always kept
  };
  Layout layout() const;
  std::vector<Panel> panels() const;
  QString pausedText() const;
  /// "16 ball–ball + 15 wall = 31 collisions", from run `runIndex`'s own counters.
  QString collisionsText(int runIndex) const;
  const Panel* panelAt(QPointF position, const std::vector<Panel>& panels) const;
  Vec2 toMetres(QPointF position) const;
  std::optional<std::size_t> ballAt(QPointF position) const;
  /// On a caption, or in the rows above every box: a click there is no use of the mouse tool.
  bool inCaptionRows(QPointF position) const;
  double temperatureTopSpeed();
  /// Fills drawn_ for this paint: every position below is drawn from it.
  void driftRuns();

  void paintBalls(QPainter& painter, const Panel& panel, std::size_t panelIndex);
  void paintBox(QPainter& painter, const Panel& panel) const;
  void paintVelocityVectors(QPainter& painter, const Panel& panel);
  void paintTethers(QPainter& painter, const Panel& panel);
  void paintCentreOfMass(QPainter& painter, const Panel& panel) const;
  void paintSelection(QPainter& painter, const Panel& panel) const;
  void paintCaptions(QPainter& painter, const std::vector<Caption>& captions) const;

  const RunController& runs_;
  bool temperature_ = false;
  bool tethers_ = true;
  bool velocityVectors_ = false;
  bool centreOfMass_ = false;
  CompareLayout compareLayout_ = CompareLayout::Overlay;
  bool toolHeld_ = false;
  QString lookFor_;                ///< the preset's caption; empty for a scene file
  bool countsCollisions_ = false;  ///< the preset's promise is a count of collisions
  bool lookForShown_ = true;

  TemperaturePalette palette_;
  double topSpeed_ = 0.0;  ///< m/s at the hot end of the temperature scale, smoothed over frames
  std::vector<QImage> ballImages_;  ///< one per panel
  DiscRasterizer rasterizer_;
  DensitySplat splat_;                    ///< the balls narrower than a pixel
  std::vector<QLineF> lines_;             ///< reused for tethers and vectors
  std::vector<std::vector<Vec2>> drawn_;  ///< m, per run: the positions drawn (driftRuns)
};

}  // namespace fooball::gui
