// CIGI 4.0 subset: IG Control, Entity Position Control, Celestial Sphere Control (with
// seconds), Atmosphere Control, Weather Control and Start of Frame against bytes written by hand from the
// CIGI 4.0 layouts (u16 size, u16 id, then the fields; CIGI 4.0 ICD, SISO-STD-013-2014, as the
// CIGI Class Library 4.0 port's Pack functions implement it), both byte orders, and errors.
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

IgControl ig4() {
  IgControl c;
  c.databaseNumber = 7;
  c.igMode = IgMode::operate;
  c.timestampValid = true;
  c.hostFrameNumber = 1234;
  c.timestamp = 500000;
  c.lastIgFrameNumber = 1233;
  return c;
}

std::vector<std::uint8_t> encode4(const Packet& p, ByteOrder order) {
  std::vector<std::uint8_t> b;
  EXPECT_EQ(appendPacket4(b, p, order), "");
  return b;
}

TEST(Cigi4, IgControlBothByteOrders) {
  // size 24, id 0, major 4, db 7, byte 6 reserved, byte 7 = operate | timestamp valid |
  // minor 0; host frame, then LAST IG FRAME, then timestamp (order differs from 3.3).
  const auto be = hexBytes("00 18 00 00 04 07 00 05 | 00 00 04 D2 00 00 04 D1 | 00 07 A1 20 00 00 00 00");
  const auto le = hexBytes("18 00 00 00 04 07 00 05 | D2 04 00 00 D1 04 00 00 | 20 A1 07 00 00 00 00 00");
  EXPECT_EQ(toHex(encode4(ig4(), ByteOrder::big)), toHex(be));
  EXPECT_EQ(toHex(encode4(ig4(), ByteOrder::little)), toHex(le));
  for (const auto* bytes : {&be, &le}) {
    const DecodedMessage d = decodeMessage(*bytes);
    ASSERT_TRUE(d.ok()) << d.error->describe();
    EXPECT_EQ(d.majorVersion, 4);
    EXPECT_EQ(d.minorVersion, 0);
    EXPECT_EQ(d.byteOrder, bytes == &be ? ByteOrder::big : ByteOrder::little);
    ASSERT_EQ(d.packets.size(), 1u);
    EXPECT_EQ(std::get<IgControl>(d.packets[0]), ig4());
  }
}

TEST(Cigi4, PosePacketsAndCelestialSeconds) {
  EntityControl e;
  e.groundOceanClamp = GroundClamp::nonConformal;
  e.parentId = 0x0304;
  e.rollDeg = -12.5f;
  e.pitchDeg = 3.25f;
  e.yawDeg = 271.0f;
  e.latitudeDeg = 47.5;
  e.longitudeDeg = 8.5;
  e.altitudeM = 450.0;
  CelestialSphereControl c;
  c.hour = 20;
  c.minute = 30;
  c.seconds = 30.5f;  // 0x41F40000: what 3.3 cannot say
  c.date = 6212026;
  c.starFieldIntensityPct = 75.0f;
  AtmosphereControl a;
  a.atmosphericModelEnable = true;
  a.globalHumidityPct = 50;
  a.airTemperatureC = 15.0f;
  a.visibilityRangeM = 10000.0f;
  a.horizontalWindSpeedMps = 2.0f;
  a.verticalWindSpeedMps = -1.0f;
  a.windDirectionDeg = 270.0f;
  a.barometricPressureHpa = 1013.25f;
  // Entity Position Control: size 48, id 1, clamp non-conformal (1 << 1), entity 0, parent.
  EXPECT_EQ(toHex(encode4(e, ByteOrder::big)),
            toHex(hexBytes("00 30 00 01 02 00 00 00 | 03 04 00 00 C1 48 00 00 | 40 50 00 00 43 87 80 00 |"
                           "40 47 C0 00 00 00 00 00 | 40 21 00 00 00 00 00 00 | 40 7C 20 00 00 00 00 00")));
  // Celestial Sphere Control: size 24, id 8, flags, reserved, hour, minute, seconds, date, intensity.
  EXPECT_EQ(toHex(encode4(c, ByteOrder::big)),
            toHex(hexBytes("00 18 00 08 1F 00 14 1E | 41 F4 00 00 00 5E C9 BA | 42 96 00 00 00 00 00 00")));
  // Atmosphere Control: size 32, id 9, humidity in bits 0-6 and the enable in bit 7 (0xB2).
  EXPECT_EQ(toHex(encode4(a, ByteOrder::big)),
            toHex(hexBytes("00 20 00 09 B2 00 00 00 | 41 70 00 00 46 1C 40 00 | 40 00 00 00 BF 80 00 00 |"
                           "43 87 00 00 44 7D 50 00")));
  for (ByteOrder order : {ByteOrder::big, ByteOrder::little}) {
    const std::vector<Packet> packets{ig4(), e, c, a};
    std::vector<std::uint8_t> b;
    ASSERT_EQ(encodeMessage4(packets, order, b), "");
    EXPECT_EQ(b.size(), 24u + 48 + 24 + 32);
    const DecodedMessage d = decodeMessage(b);
    ASSERT_TRUE(d.ok()) << d.error->describe();
    ASSERT_EQ(d.packets.size(), 4u);
    EXPECT_EQ(std::get<EntityControl>(d.packets[1]), e);
    EXPECT_EQ(std::get<CelestialSphereControl>(d.packets[2]).seconds, 30.5f);
    EXPECT_EQ(std::get<CelestialSphereControl>(d.packets[2]), c);
    EXPECT_EQ(std::get<AtmosphereControl>(d.packets[3]), a);
  }
}

TEST(Cigi4, ViewControlAndViewDefinition) {
  ViewControl v;
  v.viewId = 2;
  v.groupId = 1;
  v.xOffsetEnable = v.yOffsetEnable = v.zOffsetEnable = v.rollEnable = v.pitchEnable = v.yawEnable = true;
  v.entityId = 0x0102;
  v.xOffsetM = 1.0f;
  v.yOffsetM = -1.0f;
  v.zOffsetM = 0.5f;
  v.pitchDeg = 2.0f;
  v.yawDeg = 45.0f;
  // size 40, id 0x0F, group, enables, view id, entity id, reserved, six floats, reserved.
  EXPECT_EQ(toHex(encode4(v, ByteOrder::big)),
            toHex(hexBytes("00 28 00 0F 01 3F 00 02 | 01 02 00 00 3F 80 00 00 | BF 80 00 00 3F 00 00 00 |"
                           "00 00 00 00 40 00 00 00 | 42 34 00 00 00 00 00 00")));
  ViewDefinition d;
  d.viewId = 2;
  d.groupId = 1;
  d.nearEnable = d.farEnable = d.leftEnable = d.rightEnable = d.topEnable = d.bottomEnable = true;
  d.mirrorMode = MirrorMode::horizontal;
  d.pixelReplicationMode = 2;
  d.reorder = true;
  d.viewType = 5;
  d.nearM = 0.5f;
  d.farM = 100000.0f;
  d.leftDeg = -45.0f;
  d.rightDeg = 45.0f;
  d.topDeg = 30.0f;
  d.bottomDeg = -20.0f;
  // size 40, id 0x14, view id, group, enables | mirror, replication | reorder | type,
  // 3 reserved bytes, six floats from offset 12, reserved.
  EXPECT_EQ(toHex(encode4(d, ByteOrder::big)),
            toHex(hexBytes("00 28 00 14 00 02 01 7F | B2 00 00 00 3F 00 00 00 | 47 C3 50 00 C2 34 00 00 |"
                           "42 34 00 00 41 F0 00 00 | C1 A0 00 00 00 00 00 00")));
  const std::vector<Packet> packets{ig4(), v, d};
  std::vector<std::uint8_t> b;
  ASSERT_EQ(encodeMessage4(packets, ByteOrder::little, b), "");
  const DecodedMessage m = decodeMessage(b);
  ASSERT_TRUE(m.ok()) << m.error->describe();
  ASSERT_EQ(m.packets.size(), 3u);
  EXPECT_EQ(std::get<ViewControl>(m.packets[1]), v);
  EXPECT_EQ(std::get<ViewDefinition>(m.packets[2]), d);
}

// CCL 4.0 CigiSensorCtrlV4.cpp: size 32, id 0x10, sensor id at 4, the 3.3 flag bytes at 5
// and 6, byte 7 reserved, the view id at 8, bytes 10-11 reserved, the four floats from 12,
// bytes 28-31 reserved.
TEST(Cigi4, SensorControl) {
  const SensorControl s = sensorControlWithEveryField();
  const auto be = hexBytes("00 20 00 10 02 7B 01 00 | 00 03 00 00 3F 00 00 00 | 3E 80 00 00 3F 80 00 00 |"
                           "3E 00 00 00 00 00 00 00");
  const auto le = hexBytes("20 00 10 00 02 7B 01 00 | 03 00 00 00 00 00 00 3F | 00 00 80 3E 00 00 80 3F |"
                           "00 00 00 3E 00 00 00 00");
  EXPECT_EQ(toHex(encode4(s, ByteOrder::big)), toHex(be));
  EXPECT_EQ(toHex(encode4(s, ByteOrder::little)), toHex(le));
  for (const auto order : {ByteOrder::big, ByteOrder::little}) {
    std::vector<std::uint8_t> b = encode4(ig4(), order);
    const auto& bytes = order == ByteOrder::big ? be : le;
    b.insert(b.end(), bytes.begin(), bytes.end());
    const DecodedMessage m = decodeMessage(b);
    ASSERT_TRUE(m.ok()) << m.error->describe();
    ASSERT_EQ(m.packets.size(), 2u);
    EXPECT_EQ(std::get<SensorControl>(m.packets[1]), s);
  }
}

TEST(Cigi4, StartOfFrame) {
  StartOfFrame s;
  s.databaseNumber = -2;
  s.igMode = IgMode::operate;
  s.timestampValid = true;
  s.igFrameNumber = 0x01020304;
  s.timestamp = 100000;
  s.lastHostFrameNumber = 0xFFFFFFFF;
  const auto be = hexBytes("00 18 FF FF 04 FE 00 05 | 01 02 03 04 00 01 86 A0 | FF FF FF FF 00 00 00 00");
  EXPECT_EQ(toHex(encode4(s, ByteOrder::big)), toHex(be));
  const DecodedMessage d = decodeMessage(be);
  ASSERT_TRUE(d.ok()) << d.error->describe();
  EXPECT_EQ(std::get<StartOfFrame>(d.packets.at(0)), s);
}

// The Start of Frame the node sends a CIGI 4.0 host (docs/protocol.md's example): big-endian,
// operate, timestamp valid, WGS-84, minor version 0, no condition flags.
TEST(Cigi4, StartOfFrameAsTheNodeSendsIt) {
  StartOfFrame s;
  s.igFrameNumber = 258;
  s.timestamp = 100000;
  s.timestampValid = true;
  s.lastHostFrameNumber = 30;
  const std::vector<Packet> packets{s};
  std::vector<std::uint8_t> b;
  ASSERT_EQ(encodeMessage4(packets, ByteOrder::big, b), "");
  EXPECT_EQ(toHex(b), toHex(hexBytes("00 18 FF FF 04 00 00 05 | 00 00 01 02 00 01 86 A0 | 00 00 00 1E 00 00 00 00")));
}

TEST(Cigi4, UnknownPacketsSkippedAndErrorsNamed) {
  std::vector<std::uint8_t> b = encode4(ig4(), ByteOrder::little);
  // A CIGI 4 Entity Control (id 0x25, 16 bytes) skyig does not decode, then a 4-byte tail.
  const auto entityCtrl = hexBytes("10 00 25 00 01 00 00 00 00 00 00 00 00 00 00 00");
  b.insert(b.end(), entityCtrl.begin(), entityCtrl.end());
  DecodedMessage d = decodeMessage(b);
  ASSERT_TRUE(d.ok()) << d.error->describe();
  EXPECT_EQ(d.skippedPackets, 1u);

  auto wrong = encode4(ig4(), ByteOrder::little);
  const auto shortCelestial = hexBytes("10 00 08 00 1F 00 14 1E 00 00 00 00 00 00 00 00");  // 16, not 24
  wrong.insert(wrong.end(), shortCelestial.begin(), shortCelestial.end());
  d = decodeMessage(wrong);
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.error->kind, ErrorKind::wrongPacketSize);
  EXPECT_EQ(d.error->offset, 24u);
  EXPECT_EQ(d.error->value, 24u);
  EXPECT_NE(d.error->describe().find("CIGI 4 packet id 8 Celestial Sphere Control"), std::string::npos)
      << d.error->describe();
  EXPECT_EQ(d.packets.size(), 1u);

  auto zero = encode4(ig4(), ByteOrder::big);
  const auto z = hexBytes("00 00 00 08");
  zero.insert(zero.end(), z.begin(), z.end());
  EXPECT_EQ(decodeMessage(zero).error->kind, ErrorKind::packetSizeTooSmall);

  auto cut = encode4(ig4(), ByteOrder::big);
  cut.resize(20);
  EXPECT_EQ(decodeMessage(cut).error->kind, ErrorKind::packetPastEnd);
}

// Weather Control (0x0B, 72 bytes), CCL 4.0 CigiWeatherCtrlV4: layer, humidity, the 3.3 flags
// with the top scud enable at byte 7 bit 5, the region/entity ID at 8, the floats from 12, the
// top scud frequency and top transition band at 60 and 64, 68-71 reserved. A rain layer.
TEST(Cigi4, WeatherControlWithItsTopScudAndTransition) {
  WeatherControl w;
  w.layerId = 4;
  w.humidityPct = 90;
  w.weatherEnable = true;
  w.randomLightningEnable = true;
  w.cloudType = 8;  // nimbostratus
  w.severity = 3;
  w.topScudEnable = true;
  w.airTemperatureC = 12.5f;
  w.visibilityRangeM = 1500.0f;
  w.scudFrequencyPct = 25.0f;
  w.coveragePct = 75.0f;
  w.thicknessM = 1200.0f;
  w.transitionBandM = 50.0f;
  w.horizontalWindSpeedMps = 5.0f;
  w.verticalWindSpeedMps = -1.0f;
  w.windDirectionDeg = -90.0f;
  w.barometricPressureHpa = 1013.25f;
  w.aerosolConcentrationGpm3 = 0.5f;
  w.topScudFrequencyPct = 10.0f;
  w.topTransitionBandM = 30.0f;
  const auto be = hexBytes("00 48 00 0B 04 5A 89 2C | 00 00 00 00 41 48 00 00 | 44 BB 80 00 41 C8 00 00 |"
                           "42 96 00 00 00 00 00 00 | 44 96 00 00 42 48 00 00 | 40 A0 00 00 BF 80 00 00 |"
                           "C2 B4 00 00 44 7D 50 00 | 3F 00 00 00 41 20 00 00 | 41 F0 00 00 00 00 00 00");
  EXPECT_EQ(toHex(encode4(w, ByteOrder::big)), toHex(be));
  for (const auto order : {ByteOrder::big, ByteOrder::little}) {
    std::vector<std::uint8_t> b = encode4(ig4(), order);
    const auto bytes = encode4(w, order);
    ASSERT_EQ(bytes.size(), 72u);
    b.insert(b.end(), bytes.begin(), bytes.end());
    const DecodedMessage m = decodeMessage(b);
    ASSERT_TRUE(m.ok()) << m.error->describe();
    ASSERT_EQ(m.packets.size(), 2u);
    EXPECT_EQ(std::get<WeatherControl>(m.packets[1]), w);
  }
  // A region's layer: the ID at 8 whatever the scope says (the decoder keeps both).
  w.scope = WeatherScope::regional;
  w.entityRegionId = 0x0102;
  const auto regional = encode4(w, ByteOrder::little);
  EXPECT_EQ(toHex(std::vector<std::uint8_t>(regional.begin() + 6, regional.begin() + 12)),
            toHex(hexBytes("89 2D 02 01 00 00")));
}

TEST(Cigi4, EncoderRefusesPacketsOutsideTheSubset) {
  std::vector<std::uint8_t> b;
  EXPECT_NE(appendPacket4(b, EnvironmentalRegionControl{}, ByteOrder::big)
                .find("Environmental Region Control: not in skyig's CIGI 4.0 subset"),
            std::string::npos);
  EXPECT_TRUE(b.empty());
  AtmosphereControl a;
  a.globalHumidityPct = 128;  // 7 bits in CIGI 4
  EXPECT_EQ(appendPacket4(b, a, ByteOrder::big), "Atmosphere Control: Global Humidity = 128 does not fit in 7 bits");
}

}  // namespace
}  // namespace skyig::protocol::cigi
