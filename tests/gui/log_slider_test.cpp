#include "widgets/log_slider.h"

#include <gtest/gtest.h>

#include <QSignalSpy>
#include <QSlider>

namespace fooball::gui {
namespace {

QString plain(double value) {
  return QString::number(value);
}

TEST(LogSlider, LeftEndIsExactZeroThenLogSpacedFromMinimumToMaximum) {
  const LogSlider slider({0.01, 100.0, true}, plain);
  EXPECT_EQ(slider.valueAt(0), 0.0);
  EXPECT_DOUBLE_EQ(slider.valueAt(1), 0.01);
  EXPECT_DOUBLE_EQ(slider.valueAt(LogSlider::kPositions), 100.0);
  // Equal steps multiply the value by equal factors.
  const double ratio = slider.valueAt(101) / slider.valueAt(100);
  EXPECT_NEAR(slider.valueAt(401) / slider.valueAt(400), ratio, 1e-12);
}

TEST(LogSlider, WithoutZeroTheLeftEndIsTheMinimum) {
  const LogSlider slider({0.05, 8.0, false}, plain);
  EXPECT_DOUBLE_EQ(slider.valueAt(0), 0.05);
  EXPECT_DOUBLE_EQ(slider.valueAt(LogSlider::kPositions), 8.0);
}

TEST(LogSlider, PositionOfInvertsValueAt) {
  const LogSlider slider({0.1, 1000.0, true}, plain);
  for (int position : {0, 1, 17, 300, 599, 600})
    EXPECT_EQ(slider.positionOf(slider.valueAt(position)), position);
  EXPECT_EQ(slider.positionOf(1e9), LogSlider::kPositions);
}

TEST(LogSlider, SetValueShowsTheExactValueWithoutSignalling) {
  LogSlider slider({0.01, 100.0, true}, plain);
  QSignalSpy changed(&slider, &LogSlider::valueChanged);
  slider.setValue(9.81);
  EXPECT_EQ(slider.value(), 9.81);
  EXPECT_EQ(changed.count(), 0);
  slider.slider()->setValue(0);
  ASSERT_EQ(changed.count(), 1);
  EXPECT_EQ(changed.front().front().toDouble(), 0.0);
}

}  // namespace
}  // namespace fooball::gui
