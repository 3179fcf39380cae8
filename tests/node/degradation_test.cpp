// The degradation policy (node/frame/degradation.h): a node that cannot hold its period draws
// at a lower internal resolution after N frames, and comes back up once the level above fits.
#include "node/frame/degradation.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace {

using skyig::services::DegradationPolicy;
using skyig::services::DegradationSettings;

DegradationSettings on(int overFrames = 5, int releaseFrames = 10) {
  DegradationSettings s;
  s.enabled = true;
  s.overFrames = overFrames;
  s.releaseFrames = releaseFrames;
  return s;
}

constexpr double kPeriod = 1.0 / 60.0;

TEST(Degradation, OffNeverChangesTheResolution) {
  DegradationPolicy p(DegradationSettings{});
  for (int i = 0; i < 1000; ++i) EXPECT_EQ(p.add(1.0, kPeriod), 0);
  EXPECT_EQ(p.scale(), 1.0);
}

TEST(Degradation, DropsALevelOnlyAfterNFramesInARowOverThePeriod) {
  DegradationPolicy p(on(5));
  for (int round = 0; round < 3; ++round) {  // four slow frames and a fast one: never five in a row
    for (int i = 0; i < 4; ++i) EXPECT_EQ(p.add(2 * kPeriod, kPeriod), 0);
    EXPECT_EQ(p.add(0.5 * kPeriod, kPeriod), 0);
  }
  EXPECT_EQ(p.level(), 0);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(p.add(2 * kPeriod, kPeriod), 0);
  EXPECT_EQ(p.add(2 * kPeriod, kPeriod), +1);
  EXPECT_EQ(p.scale(), 0.75);
  for (int i = 0; i < 4; ++i) p.add(2 * kPeriod, kPeriod);
  EXPECT_EQ(p.add(2 * kPeriod, kPeriod), +1);
  EXPECT_EQ(p.scale(), 0.5);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(p.add(2 * kPeriod, kPeriod), 0) << "no level below the last";
  EXPECT_EQ(p.levelsDown(), 2u);
  EXPECT_NE(p.lastReason().find("0.50"), std::string::npos) << p.lastReason();
}

// Back up when the budget is raised: the same work under a longer period. A frame of work w at
// scale 0.5 is taken to cost 4 w at full size (pixels), so it goes up only when 4 w fits under
// the headroom.
TEST(Degradation, ComesBackUpWhenTheLevelAboveFitsTheRaisedBudget) {
  DegradationPolicy p(on(5, 10));
  for (int i = 0; i < 10; ++i) p.add(2 * kPeriod, kPeriod);
  ASSERT_EQ(p.level(), 2);
  // At 0.5, frames of 0.4 of the period would cost 0.4 * (0.75/0.5)^2 = 0.9 at 0.75: over 0.6.
  for (int i = 0; i < 50; ++i) EXPECT_EQ(p.add(0.4 * kPeriod, kPeriod), 0);
  const double raised = 4 * kPeriod;  // the budget raised: 0.9 / 4 of it fits
  for (int i = 0; i < 9; ++i) EXPECT_EQ(p.add(0.4 * kPeriod, raised), 0);
  EXPECT_EQ(p.add(0.4 * kPeriod, raised), -1);
  EXPECT_EQ(p.scale(), 0.75);
  // At 0.75 the same work costs 0.4 * (1/0.75)^2 = 0.71 of the old period at full size: under
  // 0.6 of the raised one.
  for (int i = 0; i < 9; ++i) EXPECT_EQ(p.add(0.4 * kPeriod, raised), 0);
  EXPECT_EQ(p.add(0.4 * kPeriod, raised), -1);
  EXPECT_EQ(p.scale(), 1.0);
  EXPECT_EQ(p.levelsUp(), 2u);
}

TEST(Degradation, ASlowFrameWhileUpRestartsTheCountToRelease) {
  DegradationPolicy p(on(1, 10));
  p.add(2 * kPeriod, kPeriod);
  ASSERT_EQ(p.level(), 1);
  for (int i = 0; i < 9; ++i) p.add(0.1 * kPeriod, kPeriod);
  p.add(0.9 * kPeriod, kPeriod);  // fits its own period, not the level above's headroom
  for (int i = 0; i < 9; ++i) EXPECT_EQ(p.add(0.1 * kPeriod, kPeriod), 0);
  EXPECT_EQ(p.add(0.1 * kPeriod, kPeriod), -1);
}

TEST(Degradation, NonFiniteWorkIsNotAFrame) {
  DegradationPolicy p(on(2));
  p.add(2 * kPeriod, kPeriod);
  p.add(std::numeric_limits<double>::quiet_NaN(), kPeriod);
  EXPECT_EQ(p.add(2 * kPeriod, kPeriod), +1) << "a NaN neither counts nor breaks the run";
}

TEST(Degradation, SettingsThatCannotWorkAreRefusedNamingTheValue) {
  auto refused = [](DegradationSettings s) {
    s.enabled = true;
    try {
      DegradationPolicy p(s);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  DegradationSettings s;
  s.scales = {0.5, 0.75};
  EXPECT_NE(refused(s).find("0.75"), std::string::npos);
  s.scales = {1.0};
  EXPECT_NE(refused(s).find("scales"), std::string::npos);
  s = {};
  s.releaseHeadroom = 1.2;
  EXPECT_NE(refused(s).find("release_headroom"), std::string::npos);
  s = {};
  s.overFrames = 0;
  EXPECT_NE(refused(s).find("over_frames"), std::string::npos);
}

}  // namespace
