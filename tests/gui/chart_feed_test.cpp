#include <QComboBox>

#include "charts/chart_panel.h"
#include "gui_fixture.h"
#include "settings_sidebar.h"

namespace fooball::gui::testing {
namespace {

class ChartFeed : public GuiTest {};

TEST_F(ChartFeed, SingleRunChartsReceiveSamples) {
  open(fooball::testing::gas(40));
  const std::size_t before = window->charts()->storedSampleCount(0);
  frames(30);
  EXPECT_GT(window->charts()->storedSampleCount(0), before + 5);
  EXPECT_EQ(window->charts()->storedSampleCount(1), 0u);
}

TEST_F(ChartFeed, CompareModeChartsReceiveSamplesOfBothRuns) {
  open(fooball::testing::gas(40));
  QComboBox* compare = window->sidebar()->compareBox();
  const int exact = compare->findText(QStringLiteral("exact"));
  compare->setCurrentIndex(exact);
  emit compare->activated(exact);
  ASSERT_TRUE(runs().comparing());
  frames(30);
  const std::size_t main = window->charts()->storedSampleCount(0);
  EXPECT_GT(main, 5u);
  EXPECT_EQ(window->charts()->storedSampleCount(1), main) << "the runs are sampled together";
}

TEST_F(ChartFeed, PausedRunsAddNoSamples) {
  open(fooball::testing::gas(40));
  runs().setPaused(true);
  const std::size_t before = window->charts()->storedSampleCount(0);
  frames(30);
  EXPECT_EQ(window->charts()->storedSampleCount(0), before);
}

}  // namespace
}  // namespace fooball::gui::testing
