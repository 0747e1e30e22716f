#include <QComboBox>
#include <QEvent>
#include <QPushButton>
#include <optional>

#include "chart_reading.h"
#include "charts/chart_panel.h"
#include "gui_fixture.h"
#include "sidebar/run_list_editor.h"
#include "sidebar/settings_sidebar.h"

namespace fooball::gui::testing {
namespace {

class ChartFeed : public GuiTest {};

TEST_F(ChartFeed, SingleRunChartsReceiveSamples) {
  open(fooball::testing::gas(40));
  const std::size_t before = storedSampleCount(*window->charts(), 0);
  frames(30);
  EXPECT_GT(storedSampleCount(*window->charts(), 0), before + 5);
  EXPECT_EQ(storedSampleCount(*window->charts(), 1), 0u);
}

TEST_F(ChartFeed, CompareModeChartsReceiveSamplesOfBothRuns) {
  open(fooball::testing::gas(40));
  QTest::mouseClick(window->sidebar()->runList()->addButton(), Qt::LeftButton);
  ASSERT_TRUE(runs().comparing());
  const std::size_t main = storedSampleCount(*window->charts(), 0);
  const std::size_t added = storedSampleCount(*window->charts(), 1);
  frames(30);
  const std::size_t newMain = storedSampleCount(*window->charts(), 0) - main;
  EXPECT_GT(newMain, 5u);
  EXPECT_EQ(storedSampleCount(*window->charts(), 1) - added, newMain)
      << "the runs are sampled together";
}

TEST_F(ChartFeed, PausedRunsAddNoSamples) {
  open(fooball::testing::gas(40));
  runs().setPaused(true);
  const std::size_t before = storedSampleCount(*window->charts(), 0);
  frames(30);
  EXPECT_EQ(storedSampleCount(*window->charts(), 0), before);
}

/// Calls `onPaint` when its watched widget gets a paint event.
class PaintProbe : public QObject {
 public:
  explicit PaintProbe(std::function<void()> onPaint) : onPaint_(std::move(onPaint)) {}

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override {
    if (event->type() == QEvent::Paint) onPaint_();
    return QObject::eventFilter(watched, event);
  }

 private:
  std::function<void()> onPaint_;
};

TEST_F(ChartFeed, AFramesStepsAreSampledWhileTheNextFramesStepRunsFromTheStateBeforeIt) {
  // The window's thread does not wait for a step and then sample: the sample a frame's steps
  // make due is taken while the next frame's step is out on its worker, beside the drawing,
  // from the state that step started from.
  open(fooball::testing::gas(40));
  const std::size_t initial = storedSampleCount(*window->charts(), 0);
  frames(3);  // a sample every 3 frames that step: the third makes one due
  EXPECT_EQ(storedSampleCount(*window->charts(), 0), initial) << "due, not taken yet";
  const double dueTime = group().time();
  const double dueKinetic = group().run(0).metrics().sums.kineticEnergy;

  std::optional<std::size_t> samplesWhileStepping;
  PaintProbe probe([&] {
    if (runs().stepping()) samplesWhileStepping = storedSampleCount(*window->charts(), 0);
  });
  view()->installEventFilter(&probe);
  frames(1);
  view()->removeEventFilter(&probe);
  ASSERT_TRUE(samplesWhileStepping.has_value()) << "the view is drawn while the step runs";
  EXPECT_EQ(*samplesWhileStepping, initial + 1)
      << "sampled while the step ran, before the view was drawn";
  EXPECT_GT(group().time(), dueTime);

  window->charts()->refresh();
  const QList<QPointF> kinetic = displayedPoints(*window->charts(), ChartPanel::kEnergyChart, 0);
  ASSERT_FALSE(kinetic.isEmpty());
  EXPECT_EQ(kinetic.back().x(), dueTime);
  const double factor =
      titleFactor(displayedValueAxisTitle(*window->charts(), ChartPanel::kEnergyChart));
  EXPECT_NEAR(kinetic.back().y() * factor, dueKinetic, 4e-16 * dueKinetic)
      << "the state before the step";
}

}  // namespace
}  // namespace fooball::gui::testing
