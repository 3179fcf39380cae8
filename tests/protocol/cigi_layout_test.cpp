// Byte-exact CIGI 3.3 layouts: each packet against bytes written by hand from the ICD tables
// (offsets and bit positions of CIGI ICD 3.3, sections 4.1 and 4.2, as protocol/cigi/layouts.h
// cites them), encoded and decoded. IEEE-754 patterns worked by hand, e.g. 271.0f = 0x43878000,
// 47.5 = 0x4047C00000000000.
#include <gtest/gtest.h>

#include "protocol/cigi/decoder.h"
#include "protocol/cigi/encoder.h"
#include "tests/protocol/cigi_samples.h"
#include "tests/protocol/hex.h"

namespace skyig::protocol::cigi {
namespace {

using skyig::protocol::test::hexBytes;
using skyig::protocol::test::toHex;
using skyig::protocol::cigi::test::sensorControlWithEveryField;

IgControl sampleIgControl() {
  IgControl c;
  c.databaseNumber = 7;
  c.igMode = IgMode::operate;
  c.timestampValid = true;
  c.extrapolationEnable = false;
  c.hostFrameNumber = 1234;
  c.timestamp = 500000;
  c.lastIgFrameNumber = 1233;
  return c;
}

// IG Control followed by one packet, big-endian; the packet's bytes are the expectation.
void expectLayout(const Packet& packet, std::string_view expectedHex) {
  const std::vector<std::uint8_t> expected = hexBytes(expectedHex);
  std::vector<std::uint8_t> encoded;
  ASSERT_EQ(appendPacket(encoded, packet, ByteOrder::big), "");
  EXPECT_EQ(toHex(encoded), toHex(expected)) << packetName(packetId(packet));

  // Decoding the hand-written bytes gives the packet back.
  std::vector<std::uint8_t> message;
  const Packet first = packetId(packet) == PacketId::startOfFrame ? Packet(StartOfFrame{}) : Packet(sampleIgControl());
  ASSERT_EQ(appendPacket(message, first, ByteOrder::big), "");
  message.insert(message.end(), expected.begin(), expected.end());
  const DecodedMessage d = decodeMessage(message);
  ASSERT_TRUE(d.ok()) << d.error->describe();
  ASSERT_EQ(d.packets.size(), 2u);
  EXPECT_TRUE(d.packets[1] == packet) << packetName(packetId(packet));
}

TEST(CigiLayout, IgControlBigEndian) {
  // id 1, size 24, major 3, db 7, mode operate(1) + timestamp valid(bit 2) + minor 3 (high
  // nibble), reserved, magic 80 00, host frame 1234, timestamp 500000, last IG frame 1233.
  const auto expected = hexBytes(
      "01 18 03 07 35 00 80 00 | 00 00 04 D2 00 07 A1 20 | 00 00 04 D1 00 00 00 00");
  std::vector<std::uint8_t> b;
  ASSERT_EQ(appendPacket(b, sampleIgControl(), ByteOrder::big), "");
  EXPECT_EQ(toHex(b), toHex(expected));
  const DecodedMessage d = decodeMessage(expected);
  ASSERT_TRUE(d.ok()) << d.error->describe();
  EXPECT_EQ(d.byteOrder, ByteOrder::big);
  EXPECT_EQ(d.minorVersion, 3);
  ASSERT_EQ(d.packets.size(), 1u);
  EXPECT_EQ(std::get<IgControl>(d.packets[0]), sampleIgControl());
}

TEST(CigiLayout, IgControlLittleEndian) {
  // A little-endian sender writes 0x8000 natively: bytes 00 80 on the wire, every multi-byte
  // field reversed; single bytes and bit fields are unchanged.
  const auto expected = hexBytes(
      "01 18 03 07 35 00 00 80 | D2 04 00 00 20 A1 07 00 | D1 04 00 00 00 00 00 00");
  std::vector<std::uint8_t> b;
  ASSERT_EQ(appendPacket(b, sampleIgControl(), ByteOrder::little), "");
  EXPECT_EQ(toHex(b), toHex(expected));
  const DecodedMessage d = decodeMessage(expected);
  ASSERT_TRUE(d.ok()) << d.error->describe();
  EXPECT_EQ(d.byteOrder, ByteOrder::little);
  EXPECT_EQ(std::get<IgControl>(d.packets[0]), sampleIgControl());
}

EntityControl sampleEntity() {
  EntityControl e;
  e.entityId = 0;
  e.entityState = EntityState::active;
  e.collisionDetectionEnable = true;
  e.groundOceanClamp = GroundClamp::nonConformal;
  e.animationLoop = true;
  e.animationState = AnimationState::play;
  e.extrapolationEnable = true;
  e.alpha = 255;
  e.entityType = 0x0102;
  e.parentId = 0x0304;
  e.rollDeg = -12.5f;
  e.pitchDeg = 3.25f;
  e.yawDeg = 271.0f;
  e.latitudeDeg = 47.5;
  e.longitudeDeg = 8.5;
  e.altitudeM = 450.0;
  return e;
}

TEST(CigiLayout, EntityControl) {
  // byte 4: active(1) | collision(bit 3) | clamp non-conformal (1 << 5) = 0x29
  // byte 5: loop(bit 1) | play (2 << 2) | extrapolation(bit 4) = 0x1A
  expectLayout(sampleEntity(),
               "02 30 00 00 29 1A FF 00 | 01 02 03 04 C1 48 00 00 | 40 50 00 00 43 87 80 00 |"
               "40 47 C0 00 00 00 00 00 | 40 21 00 00 00 00 00 00 | 40 7C 20 00 00 00 00 00");
}

TEST(CigiLayout, EntityControlLittleEndian) {
  std::vector<std::uint8_t> b;
  ASSERT_EQ(appendPacket(b, sampleEntity(), ByteOrder::little), "");
  EXPECT_EQ(toHex(b), toHex(hexBytes(
                          "02 30 00 00 29 1A FF 00 | 02 01 04 03 00 00 48 C1 | 00 00 50 40 00 80 87 43 |"
                          "00 00 00 00 00 C0 47 40 | 00 00 00 00 00 00 21 40 | 00 00 00 00 00 20 7C 40")));
}

TEST(CigiLayout, RateControl) {
  RateControl r;
  r.entityId = 0;
  r.articulatedPartId = 3;
  r.applyToArticulatedPart = true;
  r.localCoordinates = true;
  r.xRateMps = 1.0f;
  r.yRateMps = -1.0f;
  r.zRateMps = 0.5f;
  r.rollRateDegps = 2.0f;
  r.pitchRateDegps = 0.0f;
  r.yawRateDegps = 100.0f;
  expectLayout(r, "08 20 00 00 03 03 00 00 | 3F 80 00 00 BF 80 00 00 | 3F 00 00 00 40 00 00 00 |"
                  "00 00 00 00 42 C8 00 00");
}

TEST(CigiLayout, CelestialSphereControl) {
  CelestialSphereControl c;
  c.hour = 20;
  c.minute = 30;
  c.ephemerisModelEnable = c.sunEnable = c.moonEnable = c.starFieldEnable = c.dateTimeValid = true;
  c.date = 6212026;  // 21 June 2026 as MMDDYYYY = 0x005EC9BA
  c.starFieldIntensityPct = 75.0f;
  expectLayout(c, "09 10 14 1E 1F 00 00 00 | 00 5E C9 BA 42 96 00 00");
  c.sunEnable = false;
  c.starFieldEnable = false;
  expectLayout(c, "09 10 14 1E 15 00 00 00 | 00 5E C9 BA 42 96 00 00");
}

TEST(CigiLayout, AtmosphereControl) {
  AtmosphereControl a;
  a.atmosphericModelEnable = true;
  a.globalHumidityPct = 50;
  a.airTemperatureC = 15.0f;
  a.visibilityRangeM = 10000.0f;
  a.horizontalWindSpeedMps = 2.0f;
  a.verticalWindSpeedMps = -1.0f;
  a.windDirectionDeg = 270.0f;
  a.barometricPressureHpa = 1013.25f;
  expectLayout(a, "0A 20 01 32 41 70 00 00 | 46 1C 40 00 40 00 00 00 | BF 80 00 00 43 87 00 00 |"
                  "44 7D 50 00 00 00 00 00");
}

TEST(CigiLayout, EnvironmentalRegionControl) {
  EnvironmentalRegionControl e;
  e.regionId = 5;
  e.regionState = RegionState::active;
  e.mergeWeather = true;
  e.mergeMaritime = true;
  e.latitudeDeg = 47.5;
  e.longitudeDeg = 8.5;
  e.sizeXM = 1000.0f;
  e.sizeYM = 2000.0f;
  e.cornerRadiusM = 100.0f;
  e.rotationDeg = 45.0f;
  e.transitionPerimeterM = 500.0f;
  expectLayout(e, "0B 30 00 05 15 00 00 00 | 40 47 C0 00 00 00 00 00 | 40 21 00 00 00 00 00 00 |"
                  "44 7A 00 00 44 FA 00 00 | 42 C8 00 00 42 34 00 00 | 43 FA 00 00 00 00 00 00");
}

TEST(CigiLayout, WeatherControl) {
  WeatherControl w;
  w.entityRegionId = 5;
  w.layerId = 1;
  w.humidityPct = 80;
  w.weatherEnable = true;
  w.randomWindsEnable = true;
  w.cloudType = 7;  // cumulus
  w.scope = WeatherScope::regional;
  w.severity = 3;
  w.airTemperatureC = 15.0f;
  w.visibilityRangeM = 10000.0f;
  w.scudFrequencyPct = 0.0f;
  w.coveragePct = 50.0f;
  w.baseElevationM = 1000.0f;
  w.thicknessM = 500.0f;
  w.transitionBandM = 100.0f;
  w.horizontalWindSpeedMps = 2.0f;
  w.verticalWindSpeedMps = -1.0f;
  w.windDirectionDeg = 270.0f;
  w.barometricPressureHpa = 1013.25f;
  w.aerosolConcentrationGpm3 = 0.5f;
  // byte 6: enable(bit 0) | random winds(bit 2) | cumulus (7 << 4) = 0x75
  // byte 7: regional(1) | severity 3 << 2 = 0x0D
  expectLayout(w, "0C 38 00 05 01 50 75 0D | 41 70 00 00 46 1C 40 00 | 00 00 00 00 42 48 00 00 |"
                  "44 7A 00 00 43 FA 00 00 | 42 C8 00 00 40 00 00 00 | BF 80 00 00 43 87 00 00 |"
                  "44 7D 50 00 3F 00 00 00");
}

TEST(CigiLayout, ViewControl) {
  ViewControl v;
  v.viewId = 2;
  v.groupId = 1;
  v.xOffsetEnable = v.yOffsetEnable = v.zOffsetEnable = true;
  v.rollEnable = v.pitchEnable = v.yawEnable = true;
  v.entityId = 0;
  v.xOffsetM = 1.0f;
  v.yOffsetM = -1.0f;
  v.zOffsetM = 0.5f;
  v.rollDeg = 0.0f;
  v.pitchDeg = 2.0f;
  v.yawDeg = 45.0f;
  expectLayout(v, "10 20 00 02 01 3F 00 00 | 3F 80 00 00 BF 80 00 00 | 3F 00 00 00 00 00 00 00 |"
                  "40 00 00 00 42 34 00 00");
  v.yawEnable = false;
  v.yOffsetEnable = false;
  expectLayout(v, "10 20 00 02 01 1D 00 00 | 3F 80 00 00 BF 80 00 00 | 3F 00 00 00 00 00 00 00 |"
                  "40 00 00 00 42 34 00 00");
}

TEST(CigiLayout, ViewDefinition) {
  ViewDefinition v;
  v.viewId = 2;
  v.groupId = 1;
  v.nearEnable = v.farEnable = v.leftEnable = v.rightEnable = v.topEnable = v.bottomEnable = true;
  v.mirrorMode = MirrorMode::horizontal;
  v.pixelReplicationMode = 2;
  v.orthographic = false;
  v.reorder = true;
  v.viewType = 5;
  v.nearM = 0.5f;
  v.farM = 100000.0f;
  v.leftDeg = -45.0f;
  v.rightDeg = 45.0f;
  v.topDeg = 30.0f;
  v.bottomDeg = -20.0f;
  // byte 5: six enables 0x3F | mirror horizontal (1 << 6) = 0x7F
  // byte 6: replication 2 | reorder (bit 4) | view type 5 << 5 = 0xB2
  expectLayout(v, "15 20 00 02 01 7F B2 00 | 3F 00 00 00 47 C3 50 00 | C2 34 00 00 42 34 00 00 |"
                  "41 F0 00 00 C1 A0 00 00");
}

// CIGI ICD 3.3 / CCL CigiSensorCtrlV3.cpp: view id at 2, sensor id at 4, the flags at 5
// (on/off bit 0, polarity 1, line dropout 2, automatic gain 3, track white/black 4, track
// mode 5-7), response type at 6 bit 0, byte 7 reserved, then gain, level, AC coupling, noise.
TEST(CigiLayout, SensorControl) {
  const SensorControl s = sensorControlWithEveryField();
  // byte 5: on 0x01 | black hot 0x02 | automatic gain 0x08 | track black 0x10 | mode 3 << 5 = 0x7B
  expectLayout(s, "11 18 00 03 02 7B 01 00 | 3F 00 00 00 3E 80 00 00 | 3F 80 00 00 3E 00 00 00");
  SensorControl off;
  off.viewId = 0x0102;
  off.lineDropoutEnable = true;  // bit 2 alone: the other flags and the floats are zero
  expectLayout(off, "11 18 01 02 00 04 00 00 | 00 00 00 00 00 00 00 00 | 00 00 00 00 00 00 00 00");
  // Little-endian: the view id and the floats swap, the flag bytes do not.
  std::vector<std::uint8_t> le;
  ASSERT_EQ(appendPacket(le, s, ByteOrder::little), "");
  EXPECT_EQ(toHex(le), toHex(hexBytes("11 18 03 00 02 7B 01 00 | 00 00 00 3F 00 00 80 3E | 00 00 80 3F 00 00 00 3E")));
}

TEST(CigiLayout, StartOfFrame) {
  StartOfFrame s;
  s.databaseNumber = -2;  // the IG negates the number while it loads the database
  s.igStatus = 0;
  s.igMode = IgMode::operate;
  s.timestampValid = true;
  s.igFrameNumber = 0x01020304;
  s.timestamp = 100000;  // 1 s in 10 us ticks
  s.lastHostFrameNumber = 0xFFFFFFFF;
  const auto be = hexBytes("65 18 03 FE 00 35 80 00 | 01 02 03 04 00 01 86 A0 | FF FF FF FF 00 00 00 00");
  const auto le = hexBytes("65 18 03 FE 00 35 00 80 | 04 03 02 01 A0 86 01 00 | FF FF FF FF 00 00 00 00");
  std::vector<std::uint8_t> b;
  ASSERT_EQ(appendPacket(b, s, ByteOrder::big), "");
  EXPECT_EQ(toHex(b), toHex(be));
  b.clear();
  ASSERT_EQ(appendPacket(b, s, ByteOrder::little), "");
  EXPECT_EQ(toHex(b), toHex(le));
  for (const auto* bytes : {&be, &le}) {
    const DecodedMessage d = decodeMessage(*bytes);
    ASSERT_TRUE(d.ok()) << d.error->describe();
    EXPECT_EQ(std::get<StartOfFrame>(d.packets.at(0)), s);
  }
}

TEST(CigiLayout, BitFieldOverflowIsRejectedNamingTheField) {
  WeatherControl w;
  w.cloudType = 20;
  std::vector<std::uint8_t> b;
  EXPECT_EQ(appendPacket(b, w, ByteOrder::big), "Weather Control: Cloud Type = 20 does not fit in 4 bits");
  EXPECT_TRUE(b.empty());
  ViewDefinition v;
  v.viewType = 8;
  EXPECT_EQ(appendPacket(b, v, ByteOrder::big), "View Definition: View Type = 8 does not fit in 3 bits");
  SensorControl s;
  s.trackMode = 8;
  EXPECT_EQ(appendPacket(b, s, ByteOrder::big), "Sensor Control: Track Mode = 8 does not fit in 3 bits");
}

}  // namespace
}  // namespace skyig::protocol::cigi
