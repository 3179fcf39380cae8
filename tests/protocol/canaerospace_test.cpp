// CANaerospace: message layout against hand-written frames (spec V1.7 section 3 and the
// examples of section 5), the state decoder with FLOAT and DOUBLEH+DOUBLEL positions, an
// overridden identifier map, and malformed frames.
#include <gtest/gtest.h>

#include <cmath>

#include "protocol/canaerospace/state_decoder.h"
#include "protocol/canaerospace/state_encoder.h"
#include "tests/protocol/hex.h"

namespace skyig::protocol::canaerospace {
namespace {

CanFrame frame(std::uint32_t id, std::string_view hex) {
  const auto b = test::hexBytes(hex);
  CanFrame f;
  f.canId = id;
  f.len = static_cast<std::uint8_t>(b.size());
  for (std::size_t i = 0; i < b.size() && i < 8; ++i) f.data[i] = b[i];
  return f;
}

TEST(CanasMessage, FloatLayoutIsBigEndianAfterTheHeader) {
  // Body pitch ($137) 4.0 deg from node 10: 0A (node) 02 (FLOAT) 00 (service) 00 (code)
  // 40 80 00 00 (4.0f big-endian).
  const CanFrame expected = frame(0x137, "0A 02 00 00 40 80 00 00");
  EXPECT_EQ(toFrame(makeFloat(311, 10, 4.0f, 0)), expected);
  Message m;
  ASSERT_EQ(parseFrame(expected, m), FrameError::none);
  EXPECT_EQ(m.id, 311u);
  EXPECT_EQ(m.nodeId, 10);
  EXPECT_EQ(m.dataType, static_cast<std::uint8_t>(DataType::floatType));
  EXPECT_EQ(m.dataLength, 4);
  EXPECT_EQ(m.asFloat(), 4.0f);
}

TEST(CanasMessage, DoublePairCarriesTheHighThenLowWord) {
  // 47.5 = 0x4047C000_00000000: DOUBLEH (30 = 0x1E) then DOUBLEL (31 = 0x1F), codes 7 and 8.
  const auto pair = makeDoublePair(1036, 1, 47.5, 7);
  EXPECT_EQ(toFrame(pair[0]), frame(0x40C, "01 1E 00 07 40 47 C0 00"));
  EXPECT_EQ(toFrame(pair[1]), frame(0x40C, "01 1F 00 08 00 00 00 00"));
}

TEST(CanasMessage, DlcMustMatchTheDataType) {
  Message m;
  EXPECT_EQ(parseFrame(frame(0x137, "0A 02 00"), m), FrameError::tooShort);
  EXPECT_EQ(parseFrame(frame(0x137, "0A 02 00 00 40 80"), m), FrameError::sizeMismatch);  // FLOAT in 2 bytes
  EXPECT_EQ(parseFrame(frame(0x137, "0A 06 00 00 12 34"), m), FrameError::none);         // SHORT: DLC 6
  EXPECT_EQ(m.dataLength, 2);
  EXPECT_EQ(parseFrame(frame(0x137, "0A 00 00 00"), m), FrameError::none);               // NODATA: DLC 4
  EXPECT_EQ(parseFrame(frame(0x137, "0A 64 00 00 01"), m), FrameError::none);            // user-defined type 100
  CanFrame rtr = frame(0x137, "");
  rtr.canId |= kCanRtrFlag;
  EXPECT_EQ(parseFrame(rtr, m), FrameError::remoteFrame);
  CanFrame err = frame(0x137, "0A 02 00 00 40 80 00 00");
  err.canId |= kCanErrFlag;
  EXPECT_EQ(parseFrame(err, m), FrameError::errorFrame);
  CanFrame big = frame(0x137, "0A 02 00 00 40 80 00 00");
  big.len = 9;
  EXPECT_EQ(parseFrame(big, m), FrameError::tooLong);
}

TEST(CanasMessage, IdentifierRanges) {
  EXPECT_EQ(idRange(0), IdRange::emergencyEvent);
  EXPECT_EQ(idRange(128), IdRange::nodeServiceHigh);
  EXPECT_EQ(idRange(311), IdRange::normalOperation);
  EXPECT_EQ(idRange(1799), IdRange::normalOperation);
  EXPECT_EQ(idRange(1900), IdRange::debugService);
  EXPECT_EQ(idRange(2031), IdRange::nodeServiceLow);
  EXPECT_EQ(idRange(2032), IdRange::outside);
}

TEST(CanasState, DecodesTheStandardIdentifiers) {
  StateDecoder d;
  EXPECT_EQ(d.feed(frame(0x137, "0A 02 00 00 40 80 00 00")).status, FeedStatus::applied);  // pitch 4
  EXPECT_EQ(d.feed(frame(0x138, "0A 02 00 00 C1 48 00 00")).status, FeedStatus::applied);  // roll -12.5
  EXPECT_EQ(d.feed(frame(0x141, "0A 02 00 00 C2 B4 00 00")).status, FeedStatus::applied);  // heading -90
  EXPECT_EQ(d.feed(frame(0x40E, "0A 02 00 00 43 E1 00 00")).status, FeedStatus::applied);  // alt 450 m
  EXPECT_EQ(d.feed(frame(0x40C, "0A 1E 00 07 40 47 C0 00")).status, FeedStatus::pendingHalf);
  EXPECT_EQ(d.feed(frame(0x40C, "0A 1F 00 08 00 00 00 00")).status, FeedStatus::applied);  // lat 47.5
  EXPECT_EQ(d.feed(frame(0x40D, "0A 02 00 00 41 08 00 00")).status, FeedStatus::applied);  // lon 8.5 FLOAT
  // Spec section 5 examples: UTC 13h43m22s = 0D 2B 16 00; date 12 June 1987 = 0C 06 13 57.
  EXPECT_EQ(d.feed(frame(0x4B0, "0A 0F 00 00 0D 2B 16 00")).status, FeedStatus::applied);
  EXPECT_EQ(d.feed(frame(0x4B6, "0A 0F 00 00 0C 06 13 57")).status, FeedStatus::applied);
  const CanAerospaceState& s = d.state();
  EXPECT_EQ(s.pitchDeg, 4.0);
  EXPECT_EQ(s.rollDeg, -12.5);
  EXPECT_EQ(s.headingDeg, 270.0);  // -90 deg (+-180 convention) is 270 deg true heading
  EXPECT_EQ(s.altitudeM, 450.0);
  EXPECT_EQ(s.latitudeDeg, 47.5);
  EXPECT_EQ(s.longitudeDeg, 8.5);
  EXPECT_EQ(s.hour, 13);
  EXPECT_EQ(s.minute, 43);
  EXPECT_EQ(s.second, 22);
  EXPECT_EQ(s.year, 1987);
  EXPECT_EQ(s.month, 6);
  EXPECT_EQ(s.day, 12);
  EXPECT_TRUE(s.has(kLatitude | kLongitude | kAltitude | kHeading | kPitch | kRoll | kUtcTime | kDate));
  EXPECT_EQ(d.count(FeedStatus::applied), 8u);
}

TEST(CanasState, FieldsSeenAreTracked) {
  StateDecoder d;
  d.feed(frame(0x137, "0A 02 00 00 40 80 00 00"));
  EXPECT_TRUE(d.state().has(kPitch));
  EXPECT_FALSE(d.state().has(kRoll));
  EXPECT_FALSE(d.state().has(kPitch | kRoll));
}

TEST(CanasState, DoublePairKeepsFullPrecision) {
  // 47.450239871234 deg as FLOAT would lose ~1e-6 deg; the DOUBLEH+DOUBLEL pair keeps it all.
  CanAerospaceState in;
  in.latitudeDeg = 47.450239871234;
  in.longitudeDeg = -122.309876543219;
  StateEncoder e({}, 3, LatLonEncoding::doublePair);
  StateDecoder d;
  for (const CanFrame& f : e.encode(in, kLatitude | kLongitude)) EXPECT_TRUE(d.feed(f).ok());
  EXPECT_EQ(d.state().latitudeDeg, in.latitudeDeg);
  EXPECT_EQ(d.state().longitudeDeg, in.longitudeDeg);

  StateEncoder single({}, 3, LatLonEncoding::floatSingle);
  StateDecoder d2;
  for (const CanFrame& f : single.encode(in, kLatitude)) d2.feed(f);
  EXPECT_NE(d2.state().latitudeDeg, in.latitudeDeg);
  EXPECT_NEAR(d2.state().latitudeDeg, in.latitudeDeg, 4e-6);  // float spacing at 47 deg is 3.8e-6
}

TEST(CanasState, UnpairedOrReorderedHalvesAreRejected) {
  StateDecoder d;
  // DOUBLEL alone.
  FeedResult r = d.feed(frame(0x40C, "0A 1F 00 08 00 00 00 00"));
  EXPECT_EQ(r.status, FeedStatus::unpairedHalf);
  EXPECT_NE(r.detail.find("id 1036"), std::string::npos) << r.detail;
  // DOUBLEH code 7 then DOUBLEL code 9 (one lost in between): not combined.
  d.feed(frame(0x40C, "0A 1E 00 07 40 47 C0 00"));
  r = d.feed(frame(0x40C, "0A 1F 00 09 00 00 00 00"));
  EXPECT_EQ(r.status, FeedStatus::unpairedHalf);
  EXPECT_NE(r.detail.find("does not follow DOUBLEH code 7"), std::string::npos) << r.detail;
  EXPECT_FALSE(d.state().has(kLatitude));
  // Message codes wrap 255 -> 0.
  d.feed(frame(0x40C, "0A 1E 00 FF 40 47 C0 00"));
  EXPECT_EQ(d.feed(frame(0x40C, "0A 1F 00 00 00 00 00 00")).status, FeedStatus::applied);
  EXPECT_EQ(d.state().latitudeDeg, 47.5);
  EXPECT_EQ(d.count(FeedStatus::unpairedHalf), 2u);
}

TEST(CanasState, BadValuesAndTypesAreRejectedNamingTheId) {
  StateDecoder d;
  FeedResult r = d.feed(frame(0x137, "0A 02 00 00 42 C8 00 00"));  // pitch 100 deg
  EXPECT_EQ(r.status, FeedStatus::badValue);
  EXPECT_NE(r.detail.find("id 311"), std::string::npos) << r.detail;
  EXPECT_NE(r.detail.find("100"), std::string::npos) << r.detail;
  EXPECT_EQ(d.feed(frame(0x137, "0A 02 00 00 7F C0 00 00")).status, FeedStatus::badValue);  // NaN
  r = d.feed(frame(0x137, "0A 0C 00 00 00 10 00 20"));  // SHORT2
  EXPECT_EQ(r.status, FeedStatus::wrongDataType);
  EXPECT_NE(r.detail.find("SHORT2"), std::string::npos) << r.detail;
  EXPECT_EQ(d.feed(frame(0x4B0, "0A 0F 00 00 18 00 00 00")).status, FeedStatus::badValue);  // 24:00:00
  EXPECT_EQ(d.feed(frame(0x4B6, "0A 0F 00 00 1E 02 14 19")).status, FeedStatus::badValue);  // 30 Feb 2025
  EXPECT_EQ(d.feed(frame(0x4B6, "0A 0F 00 00 1D 02 14 18")).status, FeedStatus::applied);   // 29 Feb 2024
  EXPECT_EQ(d.feed(frame(0x137, "0A 02 00")).status, FeedStatus::malformedFrame);
  EXPECT_EQ(d.feed(frame(0x200, "0A 02 00 00 40 80 00 00")).status, FeedStatus::ignored);
  EXPECT_FALSE(d.state().has(kPitch));
}

TEST(CanasState, IdentifierMapCanBeOverridden) {
  IdentifierMap map;
  map.altitude = 332;  // true altitude instead of GPS height
  map.heading = 1133;  // true heading
  map.acceptLongLatLon1e7 = true;
  StateDecoder d(map);
  EXPECT_EQ(d.feed(frame(0x14C, "0A 02 00 00 43 E1 00 00")).status, FeedStatus::applied);
  EXPECT_EQ(d.feed(frame(0x40E, "0A 02 00 00 44 7A 00 00")).status, FeedStatus::ignored);  // no longer mapped
  EXPECT_EQ(d.state().altitudeM, 450.0);
  // LONG latitude in 1e-7 deg: 474502399 -> 47.4502399.
  EXPECT_EQ(d.feed(toFrame(makeLong(1036, 1, 474502399, 0))).status, FeedStatus::applied);
  EXPECT_NEAR(d.state().latitudeDeg, 47.4502399, 1e-12);
  StateDecoder strict;
  EXPECT_EQ(strict.feed(toFrame(makeLong(1036, 1, 474502399, 0))).status, FeedStatus::wrongDataType);
}

TEST(CanasState, NodeFilterIgnoresOtherTransmitters) {
  IdentifierMap map;
  map.nodeId = 10;
  StateDecoder d(map);
  EXPECT_EQ(d.feed(frame(0x137, "0B 02 00 00 41 20 00 00")).status, FeedStatus::ignored);  // node 11: 10 deg
  EXPECT_EQ(d.feed(frame(0x137, "0A 02 00 00 40 80 00 00")).status, FeedStatus::applied);  // node 10: 4 deg
  EXPECT_EQ(d.state().pitchDeg, 4.0);
}

TEST(CanasState, EncoderRoundTripsAStateAndCountsMessageCodes) {
  CanAerospaceState in;
  in.latitudeDeg = -33.856784;
  in.longitudeDeg = 151.215297;
  in.altitudeM = 120.5;
  in.headingDeg = 200.0;
  in.pitchDeg = -2.5;
  in.rollDeg = 15.0;
  in.hour = 21;
  in.minute = 14;
  in.second = 5;
  in.year = 2026;
  in.month = 11;
  in.day = 22;
  StateEncoder e;
  StateDecoder d;
  std::vector<CanFrame> first = e.encode(in);
  EXPECT_EQ(first.size(), 10u);  // 2 + 2 + 6 single messages
  for (const CanFrame& f : first) ASSERT_TRUE(d.feed(f).ok());
  std::vector<CanFrame> second = e.encode(in);
  for (const CanFrame& f : second) ASSERT_TRUE(d.feed(f).ok());
  EXPECT_EQ(second[0].data[3], 2);  // latitude DOUBLEH: codes 0,1 then 2,3
  EXPECT_EQ(second[4].data[3], 1);  // altitude: second message of its id
  const CanAerospaceState& s = d.state();
  EXPECT_EQ(s.latitudeDeg, in.latitudeDeg);
  EXPECT_EQ(s.longitudeDeg, in.longitudeDeg);
  EXPECT_FLOAT_EQ(static_cast<float>(s.altitudeM), 120.5f);
  EXPECT_FLOAT_EQ(static_cast<float>(s.headingDeg), 200.0f);  // sent as -160
  EXPECT_FLOAT_EQ(static_cast<float>(s.pitchDeg), -2.5f);
  EXPECT_EQ(s.second, 5);
  EXPECT_EQ(s.year, 2026);
  EXPECT_EQ(s.day, 22);
}

}  // namespace
}  // namespace skyig::protocol::canaerospace
