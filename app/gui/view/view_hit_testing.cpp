#include <algorithm>

#include "fooball/simulation.h"
#include "run/run_controller.h"
#include "view/simulation_view.h"

// SimulationView's hit-testing: which box, which point in metres and which ball a pixel is.

namespace fooball::gui {

namespace {

constexpr double kPickSlack = 4.0;  // px beyond a ball's edge that still picks it

}  // namespace

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

bool SimulationView::inCaptionRows(QPointF position) const {
  const Layout laidOut = layout();
  if (std::ranges::any_of(laidOut.captions, [&](const Caption& caption) {
        return QRectF(caption.rect).contains(position);
      })) {
    return true;
  }
  const auto boxTop = [](const Panel& panel) { return panel.transform.boxRect().top(); };
  return std::ranges::all_of(laidOut.panels,
                             [&](const Panel& panel) { return position.y() < boxTop(panel); });
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

}  // namespace fooball::gui
