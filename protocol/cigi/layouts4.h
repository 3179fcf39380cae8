#pragma once
// CIGI 4.0 layouts of the packets skyig maps onto its CIGI 3.3 structs, used both ways like
// layouts.h. Every CIGI 4 packet starts with a 16-bit size and a 16-bit id (bytes 0-3,
// written by the framework); there is no byte-swap magic: the receiver tells the order from
// how the first packet's size reads. Source: the CIGI 4.0 ICD as implemented by the CIGI
// Class Library 4.0 port (captainflasmr/cigi-ccl_4_0: CigiIGCtrlV4, CigiSOFV4,
// CigiEntityPositionCtrlV4, CigiCelestialCtrlV4, CigiAtmosCtrlV4, CigiViewCtrlV4,
// CigiViewDefV4, CigiSensorCtrlV4, CigiWeatherCtrlV4 Pack functions); the
// SISO text itself (SISO-STD-013-2014) was not available to check them against.
#include <type_traits>

#include "protocol/cigi/layouts.h"
#include "protocol/cigi/packets.h"

namespace skyig::protocol::cigi::detail {

inline constexpr std::uint8_t kCigi4Major = 4;
inline constexpr std::uint8_t kCigi4Minor = 0;

template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, IgControl>
void layout4(IO& io, P& m) {
  io.constantU8(4, kCigi4Major);
  io.i8(5, m.databaseNumber);
  // byte 6 bit 0: entity type substitution enable (not used by skyig, written 0)
  io.bits(7, 0, 2, m.igMode, "IG Mode");
  io.bits(7, 2, 1, m.timestampValid, "Timestamp Valid");
  io.bits(7, 3, 1, m.extrapolationEnable, "Smoothing Enable");
  io.constantBits(7, 4, 4, kCigi4Minor);
  io.u32(8, m.hostFrameNumber);
  io.u32(12, m.lastIgFrameNumber);  // swapped with the timestamp relative to 3.3
  io.u32(16, m.timestamp);
}

// Entity Position Control: the pose part of the 3.3 Entity Control. The state, alpha and
// animation fields live in CIGI 4's separate Entity Control packet and keep their defaults.
template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, EntityControl>
void layout4(IO& io, P& m) {
  io.bits(4, 0, 1, m.attached, "Attach State");
  io.bits(4, 1, 2, m.groundOceanClamp, "Ground/Ocean Clamp");
  io.u16(6, m.entityId);
  io.u16(8, m.parentId);
  io.f32(12, m.rollDeg);
  io.f32(16, m.pitchDeg);
  io.f32(20, m.yawDeg);
  io.f64(24, m.latitudeDeg);
  io.f64(32, m.longitudeDeg);
  io.f64(40, m.altitudeM);
}

template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, CelestialSphereControl>
void layout4(IO& io, P& m) {
  io.bits(4, 0, 1, m.ephemerisModelEnable, "Ephemeris Model Enable");
  io.bits(4, 1, 1, m.sunEnable, "Sun Enable");
  io.bits(4, 2, 1, m.moonEnable, "Moon Enable");
  io.bits(4, 3, 1, m.starFieldEnable, "Star Field Enable");
  io.bits(4, 4, 1, m.dateTimeValid, "Date/Time Valid");
  io.u8(6, m.hour);
  io.u8(7, m.minute);
  io.f32(8, m.seconds);
  io.u32(12, m.date);
  io.f32(16, m.starFieldIntensityPct);
}

template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, AtmosphereControl>
void layout4(IO& io, P& m) {
  io.bits(4, 0, 7, m.globalHumidityPct, "Global Humidity");
  io.bits(4, 7, 1, m.atmosphericModelEnable, "Atmospheric Model Enable");
  io.f32(8, m.airTemperatureC);
  io.f32(12, m.visibilityRangeM);
  io.f32(16, m.horizontalWindSpeedMps);
  io.f32(20, m.verticalWindSpeedMps);
  io.f32(24, m.windDirectionDeg);
  io.f32(28, m.barometricPressureHpa);
}

// Weather Control (0x0B, 72 bytes), from CCL 4.0 CigiWeatherCtrlV4.cpp (Pack and Unpack): the
// flags of 3.3 at 6 and 7 with the top scud enable in byte 7 bit 5, the entity or region ID moved
// to 8 (10-11 reserved), 3.3's floats from 12 instead of 8, then the top scud frequency and the
// top transition band; 68-71 reserved.
template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, WeatherControl>
void layout4(IO& io, P& m) {
  weatherLayerAndFlags(io, m);
  io.bits(7, 5, 1, m.topScudEnable, "Top Scud Enable");
  io.u16(8, m.entityRegionId);
  weatherFloats(io, m, 12);
  io.f32(60, m.topScudFrequencyPct);
  io.f32(64, m.topTransitionBandM);
}

template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, ViewControl>
void layout4(IO& io, P& m) {
  io.u8(4, m.groupId);
  io.bits(5, 0, 1, m.xOffsetEnable, "X Offset Enable");
  io.bits(5, 1, 1, m.yOffsetEnable, "Y Offset Enable");
  io.bits(5, 2, 1, m.zOffsetEnable, "Z Offset Enable");
  io.bits(5, 3, 1, m.rollEnable, "Roll Enable");
  io.bits(5, 4, 1, m.pitchEnable, "Pitch Enable");
  io.bits(5, 5, 1, m.yawEnable, "Yaw Enable");
  io.u16(6, m.viewId);
  io.u16(8, m.entityId);
  io.f32(12, m.xOffsetM);
  io.f32(16, m.yOffsetM);
  io.f32(20, m.zOffsetM);
  io.f32(24, m.rollDeg);
  io.f32(28, m.pitchDeg);
  io.f32(32, m.yawDeg);
}

// The floats start at offset 12 in the CCL 4.0 Pack function, not 8: bytes 9-11 are reserved
// after the two flag bytes.
template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, ViewDefinition>
void layout4(IO& io, P& m) {
  io.u16(4, m.viewId);
  io.u8(6, m.groupId);
  io.bits(7, 0, 1, m.nearEnable, "Near Enable");
  io.bits(7, 1, 1, m.farEnable, "Far Enable");
  io.bits(7, 2, 1, m.leftEnable, "Left Enable");
  io.bits(7, 3, 1, m.rightEnable, "Right Enable");
  io.bits(7, 4, 1, m.topEnable, "Top Enable");
  io.bits(7, 5, 1, m.bottomEnable, "Bottom Enable");
  io.bits(7, 6, 2, m.mirrorMode, "Mirror Mode");
  io.bits(8, 0, 3, m.pixelReplicationMode, "Pixel Replication Mode");
  io.bits(8, 3, 1, m.orthographic, "Projection Type");
  io.bits(8, 4, 1, m.reorder, "Reorder");
  io.bits(8, 5, 3, m.viewType, "View Type");
  io.f32(12, m.nearM);
  io.f32(16, m.farM);
  io.f32(20, m.leftDeg);
  io.f32(24, m.rightDeg);
  io.f32(28, m.topDeg);
  io.f32(32, m.bottomDeg);
}

// Sensor Control (id 0x10, 32 bytes), from CCL 4.0 CigiSensorCtrlV4.cpp (Pack and Unpack):
// the flags move ahead of the View ID, which follows at 8; bytes 7, 10-11 and 28-31 are
// reserved. Same flag bits as 3.3 (CIGI ICD 3.3 / CCL CigiSensorCtrlV3.cpp).
template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, SensorControl>
void layout4(IO& io, P& m) {
  io.u8(4, m.sensorId);
  io.bits(5, 0, 1, m.sensorOn, "Sensor On/Off");
  io.bits(5, 1, 1, m.polarity, "Polarity");
  io.bits(5, 2, 1, m.lineDropoutEnable, "Line-by-Line Dropout Enable");
  io.bits(5, 3, 1, m.automaticGain, "Automatic Gain");
  io.bits(5, 4, 1, m.trackBlack, "Track White/Black");
  io.bits(5, 5, 3, m.trackMode, "Track Mode");
  io.bits(6, 0, 1, m.gateAndTargetResponse, "Response Type");
  io.u16(8, m.viewId);
  io.f32(12, m.gain);
  io.f32(16, m.level);
  io.f32(20, m.acCoupling);
  io.f32(24, m.noise);
}

template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, StartOfFrame>
void layout4(IO& io, P& m) {
  io.constantU8(4, kCigi4Major);
  io.i8(5, m.databaseNumber);
  // byte 6 reserved; the 3.3 IG Status byte has no place in 4.0
  io.bits(7, 0, 2, m.igMode, "IG Mode");
  io.bits(7, 2, 1, m.timestampValid, "Timestamp Valid");
  io.bits(7, 3, 1, m.hostDefinedEarthModel, "Earth Reference Model");
  io.constantBits(7, 4, 4, kCigi4Minor);
  io.u32(8, m.igFrameNumber);
  io.u32(12, m.timestamp);
  io.u32(16, m.lastHostFrameNumber);
  // bytes 20-21: overframing (bit 8), paging (9), excess variable-length data (10)
}

}  // namespace skyig::protocol::cigi::detail
