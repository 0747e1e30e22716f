#include <QComboBox>
#include <vector>

#include "fooball/backend.h"
#include "gui_fixture.h"
#include "registry.h"
#include "sidebar/run_list_editor.h"
#include "sidebar/settings_sidebar.h"
#include "window/window_actions.h"

namespace fooball::gui::testing {
namespace {

class BackendSwitch : public GuiTest {};

void choose(QComboBox* box, const QString& text) {
  const int index = box->findText(text);
  ASSERT_GE(index, 0) << text.toStdString();
  box->setCurrentIndex(index);
  emit box->activated(index);
}

TEST_F(BackendSwitch, KeepsBallCountPositionsAndVelocities) {
  open(fooball::testing::gas(60));
  frames(30);
  for (const BackendInfo& info : registeredBackends()) {
    const QString name = QString::fromUtf8(info.name.data(), qsizetype(info.name.size()));
    const std::vector<Vec2> positions(mainRun().positions().begin(), mainRun().positions().end());
    const std::vector<Vec2> velocities(mainRun().velocities().begin(),
                                       mainRun().velocities().end());
    const double time = mainRun().time();
    choose(window->sidebar()->runList()->backendBox(0), name);
    EXPECT_EQ(runs().label(0), name);
    ASSERT_EQ(mainRun().ballCount(), positions.size());
    EXPECT_EQ(mainRun().time(), time) << "switching resets nothing";
    for (std::size_t i = 0; i < positions.size(); ++i) {
      // Box2D keeps floats: equal to float precision.
      EXPECT_NEAR(mainRun().positions()[i].x, positions[i].x, 1e-5);
      EXPECT_NEAR(mainRun().positions()[i].y, positions[i].y, 1e-5);
      EXPECT_NEAR(mainRun().velocities()[i].x, velocities[i].x, 1e-5);
      EXPECT_NEAR(mainRun().velocities()[i].y, velocities[i].y, 1e-5);
    }
    frames(5);
  }
}

TEST_F(BackendSwitch, OptionsFormListsTheChosenBackendsOptions) {
  open(stillBalls());
  for (const BackendInfo& info : registeredBackends()) {
    choose(window->sidebar()->runList()->backendBox(0),
           QString::fromUtf8(info.name.data(), qsizetype(info.name.size())));
    for (const OptionSpec& spec : mainRun().backend().options().specs()) {
      EXPECT_NE(window->sidebar()->findChild<QWidget*>(QStringLiteral("option_") +
                                                       QString::fromStdString(spec.name)),
                nullptr)
          << info.name << ": " << spec.name;
    }
  }
}

}  // namespace
}  // namespace fooball::gui::testing
