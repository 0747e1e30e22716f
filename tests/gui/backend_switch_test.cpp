#include <QComboBox>
#include <vector>

#include "fooball/backend.h"
#include "fooball/presets.h"
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

TEST_F(BackendSwitch, SwitchingTheDefaultPresetToChipmunkMidRunAddsNoEnergy) {
  // Issue 38 saw a +35 J jump in the energy chart on switching the default preset's run to
  // chipmunk mid-run; not reproduced on 6de8ff6. Measured at t = 5 s: the switch itself changes
  // nothing, and chipmunk's first six steps change the total by +0.02 to +0.23 J (switching at
  // every 0.25 s from 0.25 to 12 s with fooball-cli, the most it rose in 0.5 s was 0.45 J). 1 J
  // is 4× what was measured here, and 1/35 of the jump reported.
  open(loadPreset("default"));
  frames(300);
  const double before = mainRun().metrics().sums.totalEnergy();
  choose(window->sidebar()->runList()->backendBox(0), QStringLiteral("chipmunk"));
  ASSERT_EQ(runs().label(0), QStringLiteral("chipmunk"));
  EXPECT_EQ(mainRun().metrics().sums.totalEnergy(), before) << "the switch keeps the state";
  for (int frame = 1; frame <= 6; ++frame) {
    frames(1);
    EXPECT_NEAR(mainRun().metrics().sums.totalEnergy(), before, 1.0) << frame << " frames after";
  }
}

}  // namespace
}  // namespace fooball::gui::testing
