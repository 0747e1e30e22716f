#include "sample_history.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "chart_data.h"

namespace fooball::gui {
namespace {

constexpr double kEverything = -std::numeric_limits<double>::infinity();

/// Sample number `index` of a run sampled every `dt` seconds; its kinetic energy is its number,
/// so a test can tell which sample it holds.
ChartSample numberedSample(std::uint64_t index, double dt) {
  ChartSample sample;
  sample.time = static_cast<double>(index) * dt;
  sample[Quantity::KineticEnergy] = static_cast<double>(index);
  return sample;
}

std::vector<ChartSample> everything(const SampleHistory& history) {
  std::vector<ChartSample> samples;
  history.copySince(kEverything, samples);
  return samples;
}

TEST(SampleHistory, MillionSamplesStayWithinCapacityAndKeepFirstAndLatest) {
  constexpr std::size_t kWholeRun = 2000;
  constexpr std::size_t kRecent = 64;
  constexpr std::uint64_t kSamples = 1'000'000;
  SampleHistory history(kWholeRun, kRecent);
  std::size_t mostStored = 0;
  for (std::uint64_t i = 0; i < kSamples; ++i) {
    history.add(numberedSample(i, 1e-3));
    mostStored = std::max(mostStored, history.storedCount());
  }
  EXPECT_LE(mostStored, kWholeRun - 1 + kRecent);

  const std::vector<ChartSample> samples = everything(history);
  ASSERT_EQ(samples.size(), history.storedCount());
  EXPECT_EQ(samples.front()[Quantity::KineticEnergy], 0.0);
  EXPECT_EQ(samples.back()[Quantity::KineticEnergy], static_cast<double>(kSamples - 1));
  EXPECT_EQ(history.first().time, 0.0);
  EXPECT_EQ(history.latest().time, samples.back().time);
  EXPECT_EQ(history.addedCount(), kSamples);
}

TEST(SampleHistory, DecimatedRunIsEvenlySpacedThenFullResolution) {
  constexpr std::size_t kRecent = 100;
  SampleHistory history(500, kRecent);
  for (std::uint64_t i = 0; i < 100'000; ++i)
    history.add(numberedSample(i, 0.01));

  const std::vector<ChartSample> samples = everything(history);
  const double stride = static_cast<double>(history.wholeRunStride());
  EXPECT_GT(stride, 1.0);
  const std::size_t olderCount = samples.size() - kRecent;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    const double step =
        samples[i][Quantity::KineticEnergy] - samples[i - 1][Quantity::KineticEnergy];
    if (i < olderCount) {
      EXPECT_EQ(step, stride) << "at " << i;
    } else if (i > olderCount) {
      EXPECT_EQ(step, 1.0) << "at " << i;
    } else {
      EXPECT_GE(step, 1.0);
      EXPECT_LE(step, stride);
    }
  }
}

TEST(SampleHistory, DecimatedRunKeepsEveryStretchsExtremes) {
  constexpr std::uint64_t kSpikeAt = 54'321;
  SampleHistory history(100, 10);
  for (std::uint64_t i = 0; i < 1'000'000; ++i) {
    ChartSample sample = numberedSample(i, 1e-3);
    sample[Quantity::TotalEnergy] = i == kSpikeAt ? 9.0 : (i == kSpikeAt + 1 ? -9.0 : 1.0);
    history.add(sample);
  }
  ASSERT_GT(history.wholeRunStride(), 1000u);  // far coarser than the spike

  std::vector<double> times;
  std::vector<double> energies;
  history.forEachValueSince(kEverything, Quantity::TotalEnergy, [&](double time, double value) {
    times.push_back(time);
    energies.push_back(value);
  });
  EXPECT_LE(times.size(), history.valueCountSince(kEverything));
  EXPECT_TRUE(std::is_sorted(times.begin(), times.end()));
  const auto spike = std::find(energies.begin(), energies.end(), 9.0);
  ASSERT_NE(spike, energies.end());
  EXPECT_DOUBLE_EQ(times[static_cast<std::size_t>(spike - energies.begin())], kSpikeAt * 1e-3);
  EXPECT_NE(std::find(energies.begin(), energies.end(), -9.0), energies.end());
}

TEST(SampleHistory, DrawingValuesVisitEachRecentSampleOnce) {
  SampleHistory history(50, 30);
  for (std::uint64_t i = 0; i < 1000; ++i)
    history.add(numberedSample(i, 0.01));
  std::vector<double> times;
  history.forEachValueSince(kEverything, Quantity::KineticEnergy,
                            [&](double time, double) { times.push_back(time); });
  EXPECT_TRUE(std::adjacent_find(times.begin(), times.end()) == times.end());
  EXPECT_TRUE(std::is_sorted(times.begin(), times.end()));
  EXPECT_EQ(times.back(), history.latest().time);
  // The tail: the last 30 samples, every one of them.
  EXPECT_EQ(*(times.end() - 30), numberedSample(970, 0.01).time);
}

TEST(SampleHistory, WindowHoldsExactlyTheSamplesSinceItsStart) {
  SampleHistory history;
  std::vector<ChartSample> added;
  for (std::uint64_t i = 0; i < 5000; ++i) {
    added.push_back(numberedSample(i, 1.0 / 60.0));
    history.add(added.back());
  }
  for (const double window : {20.0, 0.5, 1.0 / 60.0, 0.0, 1000.0}) {
    const double since = history.latest().time - window;
    std::vector<ChartSample> shown;
    history.copySince(since, shown);

    std::vector<double> expectedTimes;
    for (const ChartSample& sample : added) {
      if (sample.time >= since) expectedTimes.push_back(sample.time);
    }
    std::vector<double> shownTimes;
    for (const ChartSample& sample : shown)
      shownTimes.push_back(sample.time);
    EXPECT_EQ(shownTimes, expectedTimes) << "window " << window << " s";
  }
}

TEST(SampleHistory, WindowLongerThanTheRecentTailContinuesWithTheDecimatedRun) {
  constexpr std::size_t kRecent = 100;
  SampleHistory history(2000, kRecent);
  for (std::uint64_t i = 0; i < 10'000; ++i)
    history.add(numberedSample(i, 0.01));

  const double since = 50.0;  // sample 5000; the tail starts at sample 9900
  std::vector<ChartSample> shown;
  history.copySince(since, shown);
  ASSERT_GT(shown.size(), kRecent);
  EXPECT_GE(shown.front().time, since);
  EXPECT_LT(shown.front().time, since + 0.01 * static_cast<double>(history.wholeRunStride()));
  EXPECT_EQ(shown.back().time, history.latest().time);
  for (std::size_t i = 1; i < shown.size(); ++i)
    EXPECT_LT(shown[i - 1].time, shown[i].time);
}

TEST(SampleHistory, TimeGoingBackStartsOver) {
  SampleHistory history;
  for (std::uint64_t i = 0; i < 100; ++i)
    history.add(numberedSample(i, 0.1));
  history.add(numberedSample(3, 0.1));
  EXPECT_EQ(history.addedCount(), 1u);
  EXPECT_EQ(history.first().time, history.latest().time);
  EXPECT_EQ(everything(history).size(), 1u);
}

// A rewind (fooball/run_history.h): the samples after its time go, the earlier stay, and the run
// continues from there without starting over. 100 samples at 0.1 s, a recent tail of 32 (times
// 6.8–9.9 s) and before it a decimated run.
TEST(SampleHistory, DropAfterKeepsThePastAndContinues) {
  SampleHistory history(16, 32);
  for (std::uint64_t i = 0; i < 100; ++i)
    history.add(numberedSample(i, 0.1));
  history.dropAfter(9.0);  // inside the tail: cut exactly
  EXPECT_DOUBLE_EQ(history.latest().time, 9.0);
  // Inside the decimated run: what is kept there is each stretch's first sample.
  const double stretch = static_cast<double>(history.wholeRunStride()) * 0.1;  // s
  history.dropAfter(5.0);
  EXPECT_LE(history.latest().time, 5.0);
  EXPECT_GT(history.latest().time, 5.0 - stretch);
  EXPECT_EQ(history.first().time, 0.0);
  for (const ChartSample& sample : everything(history))
    EXPECT_LE(sample.time, 5.0);
  history.add(numberedSample(51, 0.1));
  EXPECT_DOUBLE_EQ(history.latest().time, 5.1);
  EXPECT_EQ(history.first().time, 0.0);  // continued, not started over
}

TEST(SampleHistory, EqualTimesAreKept) {
  SampleHistory history;
  history.add(numberedSample(0, 0.1));
  history.add(numberedSample(1, 0.0));  // paused: the same time again
  EXPECT_EQ(history.addedCount(), 2u);
  EXPECT_EQ(everything(history).size(), 2u);
}

TEST(SampleHistory, NonFiniteTimeIsIgnored) {
  SampleHistory history;
  history.add(numberedSample(0, 0.1));
  ChartSample broken = numberedSample(1, 0.1);
  broken.time = std::numeric_limits<double>::quiet_NaN();
  history.add(broken);
  EXPECT_EQ(history.addedCount(), 1u);
}

TEST(SampleHistory, ClearEmptiesIt) {
  SampleHistory history(10, 10);
  for (std::uint64_t i = 0; i < 1000; ++i)
    history.add(numberedSample(i, 0.1));
  history.clear();
  EXPECT_TRUE(history.empty());
  EXPECT_EQ(history.storedCount(), 0u);
  EXPECT_EQ(history.wholeRunStride(), 1u);
  EXPECT_TRUE(everything(history).empty());
}

/// `initialEnergy` (J) is E(0), which the run's Simulation reports with every sample.
Metrics metricsAt(double time, double kineticEnergy, double residual, double initialEnergy = 0.0) {
  Metrics metrics;
  metrics.time = time;
  metrics.sums.kineticEnergy = kineticEnergy;
  metrics.sums.potentialEnergy = 2.0;
  metrics.sums.momentum = {3.0, -4.0};
  metrics.energyResidual = residual;
  metrics.initialEnergy = initialEnergy;
  return metrics;
}

TEST(ChartData, CompareModeRunsKeepIndependentHistories) {
  ChartData data;
  data.reset({"elastic", "exact"});
  ASSERT_EQ(data.runCount(), 2);
  for (int i = 0; i < 30'000; ++i)
    data.addSample(0, metricsAt(i * 0.01, 1.0, 0.0), {});
  for (int i = 0; i < 10; ++i)
    data.addSample(1, metricsAt(5.0 + i * 0.5, 7.0, 0.0), {});

  EXPECT_EQ(data.history(0).addedCount(), 30'000u);
  EXPECT_EQ(data.history(1).addedCount(), 10u);
  EXPECT_EQ(data.history(1).storedCount(), 10u);
  EXPECT_EQ(data.history(1).first().time, 5.0);
  EXPECT_EQ(data.history(1).latest()[Quantity::KineticEnergy], 7.0);
  EXPECT_EQ(data.history(0).latest()[Quantity::KineticEnergy], 1.0);
  EXPECT_EQ(data.startTime(), 0.0);
  EXPECT_DOUBLE_EQ(data.endTime(), 299.99);

  // Run 1 starting over leaves run 0 alone.
  data.addSample(1, metricsAt(0.0, 7.0, 0.0), {});
  EXPECT_EQ(data.history(1).addedCount(), 1u);
  EXPECT_EQ(data.history(0).addedCount(), 30'000u);
}

TEST(ChartData, SampleHoldsTheChartedQuantities) {
  ChartData data;
  data.reset({"elastic"});
  data.addSample(0, metricsAt(0.0, 6.0, 0.0, 8.0), {});  // E₀ = 6 + 2 = 8 J
  data.addSample(0, metricsAt(0.1, 5.0, -0.5, 8.0), {});
  const ChartSample& sample = data.history(0).latest();
  EXPECT_EQ(sample[Quantity::MomentumX], 3.0);
  EXPECT_EQ(sample[Quantity::MomentumY], -4.0);
  EXPECT_EQ(sample[Quantity::MomentumMagnitude], 5.0);
  EXPECT_EQ(sample[Quantity::KineticEnergy], 5.0);
  EXPECT_EQ(sample[Quantity::PotentialEnergy], 2.0);
  EXPECT_EQ(sample[Quantity::TotalEnergy], 7.0);
  EXPECT_EQ(sample[Quantity::EnergyResidual], -0.5);
  EXPECT_EQ(sample[Quantity::RelativeEnergyResidual], -0.5 / 8.0);
}

// The chart once took E₀ from its own first sample, so a history that began mid-run (a run added
// to the charts later, or charts reset) divided by the energy then, not by the run's E(0).
TEST(ChartData, RelativeResidualIsAgainstTheRunsInitialEnergyWhereverTheHistoryBegins) {
  ChartData data;
  data.reset({"elastic"});
  data.addSample(0, metricsAt(3.0, 18.0, -1.0, 10.0), {});  // E = 20 J now, E(0) = 10 J
  EXPECT_EQ(data.history(0).latest()[Quantity::RelativeEnergyResidual], -0.1);
}

TEST(ChartData, RelativeResidualIsUndefinedForZeroInitialEnergy) {
  ChartData data;
  data.reset({"elastic"});
  data.addSample(0, metricsAt(0.0, -2.0, 0.0), {});  // E₀ = −2 + 2 = 0 J
  data.addSample(0, metricsAt(0.1, -2.0, 1e-9), {});
  EXPECT_TRUE(std::isnan(data.history(0).latest()[Quantity::RelativeEnergyResidual]));
}

TEST(ChartData, ResetForgetsSamplesAndMarkersAndIgnoresUnnamedRuns) {
  ChartData data;
  data.reset({"elastic", "exact"});
  data.addSample(0, metricsAt(0.0, 1.0, 0.0), {});
  data.addMarker(0.0, "grab");
  data.reset({"box2d"});
  EXPECT_FALSE(data.hasSamples());
  EXPECT_TRUE(data.markers().empty());
  EXPECT_EQ(data.runNames(), QStringList{"box2d"});
  data.addSample(1, metricsAt(0.0, 1.0, 0.0), {});
  EXPECT_FALSE(data.hasSamples());
}

TEST(ChartData, AddingRemovingAndRenamingRunsKeepsTheOthersHistories) {
  ChartData data;
  data.reset({"elastic"});
  for (int i = 0; i < 5; ++i)
    data.addSample(0, metricsAt(i * 0.1, 1.0, 0.0), {});
  data.addRun("exact");
  data.addRun("box2d");
  ASSERT_EQ(data.runCount(), 3);
  EXPECT_EQ(data.history(0).addedCount(), 5u);
  EXPECT_TRUE(data.history(1).empty());
  data.addSample(1, metricsAt(0.5, 2.0, 0.0), {});
  data.addSample(2, metricsAt(0.5, 3.0, 0.0), {});
  data.addSample(2, metricsAt(0.6, 3.0, 0.0), {});

  data.renameRun(2, "box2d:substeps=8");
  EXPECT_EQ(data.runNames(), (QStringList{"elastic", "exact", "box2d:substeps=8"}));
  EXPECT_EQ(data.history(2).addedCount(), 2u);

  data.removeRun(1);
  EXPECT_EQ(data.runNames(), (QStringList{"elastic", "box2d:substeps=8"}));
  EXPECT_EQ(data.history(0).addedCount(), 5u);
  EXPECT_EQ(data.history(1).addedCount(), 2u);
  EXPECT_EQ(data.history(1).latest()[Quantity::KineticEnergy], 3.0);
  // The moved run's samples still land in its own history, against its own E(0) (5 J).
  data.addSample(1, metricsAt(0.7, 3.0, 1.0, 5.0), {});
  EXPECT_EQ(data.history(1).latest()[Quantity::RelativeEnergyResidual], 1.0 / 5.0);

  for (int i = 0; i < 10; ++i)
    data.addRun("xpbd");
  EXPECT_EQ(data.runCount(), ChartData::kMaxRuns);
  while (data.runCount() > 1)
    data.removeRun(data.runCount() - 1);
  data.removeRun(0);  // the last run stays
  EXPECT_EQ(data.runCount(), 1);
  EXPECT_EQ(data.history(0).addedCount(), 5u);
}

TEST(ChartData, BaselineSamplesAreKeptWhileItIsShown) {
  ChartData data;
  data.reset({"elastic", "exact"});
  Divergence divergence;
  divergence.rmsPositionDifference = 2e-9;
  divergence.maxPositionDifference = 5e-9;
  data.addSample(ChartData::kBaseline, metricsAt(0.0, 1.0, 0.0), divergence);  // not shown
  EXPECT_TRUE(data.history(ChartData::kBaseline).empty());
  data.setBaselineShown(true);
  data.addSample(ChartData::kBaseline, metricsAt(4.0, 1.0, 0.0), divergence);
  ASSERT_EQ(data.history(ChartData::kBaseline).addedCount(), 1u);
  EXPECT_EQ(data.history(ChartData::kBaseline).latest()[Quantity::RmsPositionDifference], 2e-9);
  EXPECT_EQ(data.history(ChartData::kBaseline).latest()[Quantity::MaxPositionDifference], 5e-9);
  EXPECT_TRUE(data.hasSamples());
  EXPECT_EQ(data.endTime(), 4.0);
  data.setBaselineShown(false);
  EXPECT_TRUE(data.history(ChartData::kBaseline).empty());
  EXPECT_FALSE(data.hasSamples());
}

TEST(ChartData, MarkersAreBounded) {
  ChartData data;
  for (std::size_t i = 0; i < ChartData::kMaxMarkers + 10; ++i) {
    data.addMarker(static_cast<double>(i), "gravity");
  }
  EXPECT_EQ(data.markers().size(), ChartData::kMaxMarkers);
  EXPECT_EQ(data.markers().front().time, 10.0);
}

}  // namespace
}  // namespace fooball::gui
