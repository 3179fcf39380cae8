// Background rebuilds: the previous model stays available, the latest request wins, a bad
// request leaves the last good model in place.
#include <gtest/gtest.h>

#include "render/atmosphere/conditions.h"
#include "render/atmosphere/updater.h"
#include "shared_models.h"

namespace skyig::atmosphere {
namespace {

ModelConfig tinyConfig(double albedo) {
  ModelConfig c = testing::oneGroupConfig();
  c.sizes = testing::tinySizes();
  c.options.scattering_orders = 2;
  c.medium.ground_albedo = albedo;
  return c;
}

TEST(AtmosphereUpdater, LatestRequestWinsAndTheOldModelServesMeanwhile) {
  const auto dir = testing::testCacheDirectory() / "updater";
  AtmosphereUpdater updater(tinyConfig(0.1), dir);
  const auto first = updater.current();
  ASSERT_TRUE(first);
  EXPECT_EQ(updater.generation(), 0u);
  updater.request(tinyConfig(0.2));
  updater.request(tinyConfig(0.3));
  // Whatever the worker is doing, current() answers with a complete model.
  EXPECT_TRUE(updater.current());
  updater.waitIdle();
  const auto latest = updater.current();
  EXPECT_DOUBLE_EQ(latest->config().medium.ground_albedo, 0.3);
  EXPECT_GE(updater.generation(), 1u);
  EXPECT_LE(updater.generation(), 2u);
  // The snapshot handed out before is untouched and still usable.
  EXPECT_DOUBLE_EQ(first->config().medium.ground_albedo, 0.1);
  EXPECT_EQ(updater.lastError(), "");
}

TEST(AtmosphereUpdater, BadRequestKeepsTheLastGoodModel) {
  const auto dir = testing::testCacheDirectory() / "updater";
  AtmosphereUpdater updater(tinyConfig(0.1), dir);
  ModelConfig bad = tinyConfig(0.1);
  bad.medium.mie_phase_g = 1.5;
  updater.request(bad);
  updater.waitIdle();
  EXPECT_NE(updater.lastError().find("mie_phase_g = 1.5"), std::string::npos) << updater.lastError();
  EXPECT_DOUBLE_EQ(updater.current()->config().medium.mie_phase_g, 0.8);
  EXPECT_EQ(updater.generation(), 0u);
}

}  // namespace
}  // namespace skyig::atmosphere
