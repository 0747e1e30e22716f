#include "marker_labels.h"

#include <gtest/gtest.h>

#include <random>

namespace fooball::gui {
namespace {

const QRectF kPlot(50.0, 20.0, 600.0, 200.0);
constexpr double kRowHeight = 14.0;
constexpr int kRows = 2;
constexpr double kGap = 6.0;

void expectApartAndInside(const std::vector<std::optional<QRectF>>& rects,
                          const std::vector<MarkerLabelRequest>& labels) {
  ASSERT_EQ(rects.size(), labels.size());
  for (std::size_t i = 0; i < rects.size(); ++i) {
    if (!rects[i]) continue;
    EXPECT_TRUE(kPlot.contains(*rects[i])) << i << " leaves the plot";
    EXPECT_DOUBLE_EQ(rects[i]->width(), labels[i].width);
    // Beside its own line: starting just right of it or ending just left of it.
    EXPECT_TRUE(std::abs(rects[i]->left() - labels[i].x) <= 2.0 + 1e-9 ||
                std::abs(rects[i]->right() - labels[i].x) <= 2.0 + 1e-9)
        << i;
    for (std::size_t j = i + 1; j < rects.size(); ++j) {
      if (rects[j]) {
        EXPECT_FALSE(rects[i]->intersects(*rects[j])) << i << " and " << j;
      }
    }
  }
}

TEST(MarkerLabels, NeighboursShareNoPixel) {
  // A drag's worth of markers a few pixels apart, then two far apart.
  std::vector<MarkerLabelRequest> labels;
  for (int i = 0; i < 12; ++i)
    labels.push_back({100.0 + 4.0 * i, 70.0});
  labels.push_back({400.0, 90.0});
  labels.push_back({405.0, 90.0});
  const auto rects = layoutMarkerLabels(labels, kPlot, kRowHeight, kRows, kGap);
  expectApartAndInside(rects, labels);
  EXPECT_TRUE(rects.front().has_value()) << "the first always has room";
  EXPECT_TRUE(rects[12].has_value() && rects[13].has_value()) << "two rows for two close labels";
}

TEST(MarkerLabels, ANewestMarkerAtTheRightEdgeIsLabelledInsideThePlot) {
  // The scrolling window puts the latest change at the right edge: its label turns left.
  const std::vector<MarkerLabelRequest> labels{{kPlot.right() - 3.0, 80.0}};
  const auto rects = layoutMarkerLabels(labels, kPlot, kRowHeight, kRows, kGap);
  ASSERT_TRUE(rects[0].has_value());
  EXPECT_LE(rects[0]->right(), kPlot.right());
  expectApartAndInside(rects, labels);
}

TEST(MarkerLabels, RandomMarkersInAnyOrderNeverOverlap) {
  std::mt19937 random(13);
  std::uniform_real_distribution<double> x(kPlot.left(), kPlot.right());
  std::uniform_real_distribution<double> width(20.0, 160.0);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<MarkerLabelRequest> labels(1 + trial % 25);
    for (MarkerLabelRequest& label : labels)
      label = {x(random), width(random)};
    expectApartAndInside(layoutMarkerLabels(labels, kPlot, kRowHeight, kRows, kGap), labels);
  }
}

TEST(MarkerLabels, TooWideForThePlotIsLeftOut) {
  const std::vector<MarkerLabelRequest> labels{{100.0, kPlot.width() + 1.0}};
  EXPECT_FALSE(layoutMarkerLabels(labels, kPlot, kRowHeight, kRows, kGap)[0].has_value());
}

}  // namespace
}  // namespace fooball::gui
