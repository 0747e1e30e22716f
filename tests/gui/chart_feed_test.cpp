#include <QComboBox>
#include <QPushButton>

#include "charts/chart_panel.h"
#include "gui_fixture.h"
#include "run_list_editor.h"
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
  QTest::mouseClick(window->sidebar()->runList()->addButton(), Qt::LeftButton);
  ASSERT_TRUE(runs().comparing());
  const std::size_t main = window->charts()->storedSampleCount(0);
  const std::size_t added = window->charts()->storedSampleCount(1);
  frames(30);
  const std::size_t newMain = window->charts()->storedSampleCount(0) - main;
  EXPECT_GT(newMain, 5u);
  EXPECT_EQ(window->charts()->storedSampleCount(1) - added, newMain)
      << "the runs are sampled together";
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
