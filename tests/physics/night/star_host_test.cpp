// The host's star field (CIGI Celestial Sphere Control) reaches the HostState the worker
// builds the sky from: intensity as a fraction, 0 when disabled, bad values refused.
#include "node/host/cigi_state.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace skyig;
using namespace skyig::services;
namespace cigi = skyig::protocol::cigi;

namespace {

int apply(CigiStateTracker& t, bool enable, float percent, bool dateValid = false) {
  cigi::CelestialSphereControl cs;
  cs.starFieldEnable = enable;
  cs.starFieldIntensityPct = percent;
  cs.dateTimeValid = dateValid;
  cigi::DecodedMessage m;
  m.packets = {cs};
  return t.apply(m, Clock::now());
}

}  // namespace

TEST(StarFieldHost, CelestialSphereControlSetsTheStarFieldIntensity) {
  CigiStateTracker t;
  EXPECT_EQ(t.state().starFieldIntensity, 1.0);  // stars at full strength until the host says otherwise
  EXPECT_EQ(apply(t, true, 40.0f), 0);
  EXPECT_NEAR(t.state().starFieldIntensity, 0.4, 1e-7);
  EXPECT_EQ(apply(t, false, 80.0f, true), 0);
  EXPECT_EQ(t.state().starFieldIntensity, 0.0);
  EXPECT_EQ(apply(t, true, 100.0f), 0);
  EXPECT_EQ(t.state().starFieldIntensity, 1.0);
  EXPECT_EQ(apply(t, true, std::nanf("")), 1);
  EXPECT_EQ(apply(t, true, 150.0f), 1);
  EXPECT_EQ(t.state().starFieldIntensity, 1.0);  // the last good value kept
}
