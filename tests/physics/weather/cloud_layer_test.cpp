// Cloud layers as a host gives them (physics/weather/cloud_layer.h): CIGI's ten types in the
// WMO's three families, their names both ways, and the values a layer cannot be drawn with.
#include "physics/weather/cloud_layer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace {

using skyig::sky::CloudLayer;
using skyig::sky::CloudType;
using namespace skyig::weather;

TEST(CloudLayer, CigisTenTypesFallInTheAtlassThreeFamilies) {
  int stratiform = 0, cumuliform = 0, cirriform = 0;
  for (int v = 1; v <= 10; ++v) {
    const auto type = cloudTypeOfCigi(v);
    ASSERT_TRUE(type) << v;
    EXPECT_EQ(parseCloudType(toString(*type)), type) << toString(*type);
    switch (familyOf(*type)) {
      case CloudFamily::Stratiform: ++stratiform; break;
      case CloudFamily::Cumuliform: ++cumuliform; break;
      case CloudFamily::Cirriform: ++cirriform; break;
    }
  }
  EXPECT_EQ(stratiform, 5);  // stratus, nimbostratus, altostratus, stratocumulus; altocumulus
  EXPECT_EQ(cumuliform, 2);  // cumulus, cumulonimbus
  EXPECT_EQ(cirriform, 3);   // cirrus, cirrostratus, cirrocumulus
  EXPECT_EQ(familyOf(CloudType::Cumulonimbus), CloudFamily::Cumuliform);
  EXPECT_EQ(familyOf(CloudType::Cirrostratus), CloudFamily::Cirriform);
  EXPECT_EQ(toString(CloudType::Stratus), "stratus");  // CIGI's value 10
  EXPECT_FALSE(cloudTypeOfCigi(0)) << "none";
  EXPECT_FALSE(cloudTypeOfCigi(11)) << "other";
  EXPECT_FALSE(parseCloudType("fog"));
}

TEST(CloudLayer, ValuesALayerCannotBeDrawnWithAreRefusedByName) {
  const CloudLayer deck = parseCloudSpec("stratus:300:400");  // coverage 100 when not given
  EXPECT_TRUE(deck.enabled);
  EXPECT_EQ(deck.coveragePct, 100.0);
  EXPECT_NO_THROW(validate(deck));
  EXPECT_EQ(parseCloudSpec("cumulus:1200:1500:50").coveragePct, 50.0);
  // The wind that moves it: speed and the direction it blows from, both or neither.
  const CloudLayer windy = parseCloudSpec("cumulus:1200:800:50:10:270");
  EXPECT_EQ(windy.windSpeedMps, 10.0);
  EXPECT_EQ(windy.windFromDeg, 270.0);
  EXPECT_EQ(deck.windSpeedMps, 0.0);
  EXPECT_THROW(parseCloudSpec("cumulus:1200:800:50:10"), std::invalid_argument);
  EXPECT_THROW(parseCloudSpec("cumulus:1200:800:50:-3:270"), std::invalid_argument);
  EXPECT_THROW(parseCloudSpec("cumulus:1200:800:50:10:270:5"), std::invalid_argument);
  EXPECT_THROW(parseCloudSpec("stratus:300"), std::invalid_argument);
  EXPECT_THROW(parseCloudSpec("stratus:300:4oo"), std::invalid_argument);
  EXPECT_THROW(parseCloudSpec("stratus:300:400:150"), std::invalid_argument);
  auto refusal = [&](auto spoil) {
    CloudLayer bad = deck;
    spoil(bad);
    try {
      validate(bad);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(refusal([](CloudLayer& l) { l.baseM = std::nan(""); }).find("base"), std::string::npos);
  EXPECT_NE(refusal([](CloudLayer& l) { l.thicknessM = 0.0; }).find("thickness"), std::string::npos);
  EXPECT_NE(refusal([](CloudLayer& l) { l.coveragePct = 100.5; }).find("coverage"), std::string::npos);
  EXPECT_NE(refusal([](CloudLayer& l) { l.severity = 6; }).find("severity"), std::string::npos);
  EXPECT_NE(refusal([](CloudLayer& l) { l.windSpeedMps = -1.0; }).find("wind speed"), std::string::npos);
  CloudLayer off;
  off.thicknessM = std::nan("");
  EXPECT_NO_THROW(validate(off)) << "a layer that is off is never drawn";
  EXPECT_EQ(describe(deck), "stratus base 300 m, 400 m thick, 100 % cover, severity 2");
  EXPECT_EQ(describe(off), "off");
}

}  // namespace
