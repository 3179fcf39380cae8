#pragma once
// CIGI 3.3 packet layouts, written once and used both ways: layout(io, packet) visits every
// field with its byte offset, and the IO object either packs (cigi/encoder.cpp) or unpacks
// (cigi/decoder.cpp). Offsets and bit positions follow the ICD tables (CIGI ICD 3.3, the
// Boeing CIGI 3.3 Interface Control Document, sections 4.1 host-to-IG and 4.2 IG-to-host
// packets; cross-checked with the CIGI Class Library 3.3.3 Pack() functions and Wireshark's
// epan/dissectors/packet-cigi.c). Bits count from
// 0 = least significant. Bytes 0 and 1 (packet id and size) are written by the framework.
// The tests pin each layout with hand-written bytes (tests/protocol/cigi_layout_test.cpp).
#include <cstddef>
#include <type_traits>

#include "protocol/cigi/packets.h"

namespace skyig::protocol::cigi::detail {

template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, IgControl>
void layout(IO& io, P& m) {
  io.constantU8(2, kMajorVersion);
  io.i8(3, m.databaseNumber);
  io.bits(4, 0, 2, m.igMode, "IG Mode");
  io.bits(4, 2, 1, m.timestampValid, "Timestamp Valid");
  io.bits(4, 3, 1, m.extrapolationEnable, "Extrapolation/Interpolation Enable");
  io.constantBits(4, 4, 4, kMinorVersion);
  io.constantU16(6, kByteSwapMagic);
  io.u32(8, m.hostFrameNumber);
  io.u32(12, m.timestamp);
  io.u32(16, m.lastIgFrameNumber);
}

template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, EntityControl>
void layout(IO& io, P& m) {
  io.u16(2, m.entityId);
  io.bits(4, 0, 2, m.entityState, "Entity State");
  io.bits(4, 2, 1, m.attached, "Attach State");
  io.bits(4, 3, 1, m.collisionDetectionEnable, "Collision Detection Enable");
  io.bits(4, 4, 1, m.inheritAlpha, "Inherit Alpha");
  io.bits(4, 5, 2, m.groundOceanClamp, "Ground/Ocean Clamp");
  io.bits(5, 0, 1, m.animationDirectionBackward, "Animation Direction");
  io.bits(5, 1, 1, m.animationLoop, "Animation Loop Mode");
  io.bits(5, 2, 2, m.animationState, "Animation State");
  io.bits(5, 4, 1, m.extrapolationEnable, "Extrapolation/Interpolation Enable");
  io.u8(6, m.alpha);
  io.u16(8, m.entityType);
  io.u16(10, m.parentId);
  io.f32(12, m.rollDeg);
  io.f32(16, m.pitchDeg);
  io.f32(20, m.yawDeg);
  io.f64(24, m.latitudeDeg);
  io.f64(32, m.longitudeDeg);
  io.f64(40, m.altitudeM);
}

template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, RateControl>
void layout(IO& io, P& m) {
  io.u16(2, m.entityId);
  io.u8(4, m.articulatedPartId);
  io.bits(5, 0, 1, m.applyToArticulatedPart, "Apply to Articulated Part");
  io.bits(5, 1, 1, m.localCoordinates, "Coordinate System");
  io.f32(8, m.xRateMps);
  io.f32(12, m.yRateMps);
  io.f32(16, m.zRateMps);
  io.f32(20, m.rollRateDegps);
  io.f32(24, m.pitchRateDegps);
  io.f32(28, m.yawRateDegps);
}

template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, CelestialSphereControl>
void layout(IO& io, P& m) {
  io.u8(2, m.hour);
  io.u8(3, m.minute);
  io.bits(4, 0, 1, m.ephemerisModelEnable, "Ephemeris Model Enable");
  io.bits(4, 1, 1, m.sunEnable, "Sun Enable");
  io.bits(4, 2, 1, m.moonEnable, "Moon Enable");
  io.bits(4, 3, 1, m.starFieldEnable, "Star Field Enable");
  io.bits(4, 4, 1, m.dateTimeValid, "Date/Time Valid");
  io.u32(8, m.date);
  io.f32(12, m.starFieldIntensityPct);
}

template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, AtmosphereControl>
void layout(IO& io, P& m) {
  io.bits(2, 0, 1, m.atmosphericModelEnable, "Atmospheric Model Enable");
  io.u8(3, m.globalHumidityPct);
  io.f32(4, m.airTemperatureC);
  io.f32(8, m.visibilityRangeM);
  io.f32(12, m.horizontalWindSpeedMps);
  io.f32(16, m.verticalWindSpeedMps);
  io.f32(20, m.windDirectionDeg);
  io.f32(24, m.barometricPressureHpa);
}

template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, EnvironmentalRegionControl>
void layout(IO& io, P& m) {
  io.u16(2, m.regionId);
  io.bits(4, 0, 2, m.regionState, "Region State");
  io.bits(4, 2, 1, m.mergeWeather, "Merge Weather Properties");
  io.bits(4, 3, 1, m.mergeAerosol, "Merge Aerosol Concentrations");
  io.bits(4, 4, 1, m.mergeMaritime, "Merge Maritime Surface Conditions");
  io.bits(4, 5, 1, m.mergeTerrestrial, "Merge Terrestrial Surface Conditions");
  io.f64(8, m.latitudeDeg);
  io.f64(16, m.longitudeDeg);
  io.f32(24, m.sizeXM);
  io.f32(28, m.sizeYM);
  io.f32(32, m.cornerRadiusM);
  io.f32(36, m.rotationDeg);
  io.f32(40, m.transitionPerimeterM);
}

// Weather Control's layer, humidity and flag bytes (4-7) and its twelve floats from `floats`: the
// same in CIGI 3.3 (floats from 8) and 4.0 (from 12, layouts4.h).
template <class IO, class P>
void weatherLayerAndFlags(IO& io, P& m) {
  io.u8(4, m.layerId);
  io.u8(5, m.humidityPct);
  io.bits(6, 0, 1, m.weatherEnable, "Weather Enable");
  io.bits(6, 1, 1, m.scudEnable, "Scud Enable");
  io.bits(6, 2, 1, m.randomWindsEnable, "Random Winds Enable");
  io.bits(6, 3, 1, m.randomLightningEnable, "Random Lightning Enable");
  io.bits(6, 4, 4, m.cloudType, "Cloud Type");
  io.bits(7, 0, 2, m.scope, "Scope");
  io.bits(7, 2, 3, m.severity, "Severity");
}
template <class IO, class P>
void weatherFloats(IO& io, P& m, std::size_t floats) {
  io.f32(floats, m.airTemperatureC);
  io.f32(floats + 4, m.visibilityRangeM);
  io.f32(floats + 8, m.scudFrequencyPct);
  io.f32(floats + 12, m.coveragePct);
  io.f32(floats + 16, m.baseElevationM);
  io.f32(floats + 20, m.thicknessM);
  io.f32(floats + 24, m.transitionBandM);
  io.f32(floats + 28, m.horizontalWindSpeedMps);
  io.f32(floats + 32, m.verticalWindSpeedMps);
  io.f32(floats + 36, m.windDirectionDeg);
  io.f32(floats + 40, m.barometricPressureHpa);
  io.f32(floats + 44, m.aerosolConcentrationGpm3);
}

template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, WeatherControl>
void layout(IO& io, P& m) {
  io.u16(2, m.entityRegionId);
  weatherLayerAndFlags(io, m);
  weatherFloats(io, m, 8);
}

template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, ViewControl>
void layout(IO& io, P& m) {
  io.u16(2, m.viewId);
  io.u8(4, m.groupId);
  io.bits(5, 0, 1, m.xOffsetEnable, "X Offset Enable");
  io.bits(5, 1, 1, m.yOffsetEnable, "Y Offset Enable");
  io.bits(5, 2, 1, m.zOffsetEnable, "Z Offset Enable");
  io.bits(5, 3, 1, m.rollEnable, "Roll Enable");
  io.bits(5, 4, 1, m.pitchEnable, "Pitch Enable");
  io.bits(5, 5, 1, m.yawEnable, "Yaw Enable");
  io.u16(6, m.entityId);
  io.f32(8, m.xOffsetM);
  io.f32(12, m.yOffsetM);
  io.f32(16, m.zOffsetM);
  io.f32(20, m.rollDeg);
  io.f32(24, m.pitchDeg);
  io.f32(28, m.yawDeg);
}

template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, ViewDefinition>
void layout(IO& io, P& m) {
  io.u16(2, m.viewId);
  io.u8(4, m.groupId);
  io.bits(5, 0, 1, m.nearEnable, "Near Enable");
  io.bits(5, 1, 1, m.farEnable, "Far Enable");
  io.bits(5, 2, 1, m.leftEnable, "Left Enable");
  io.bits(5, 3, 1, m.rightEnable, "Right Enable");
  io.bits(5, 4, 1, m.topEnable, "Top Enable");
  io.bits(5, 5, 1, m.bottomEnable, "Bottom Enable");
  io.bits(5, 6, 2, m.mirrorMode, "Mirror Mode");
  io.bits(6, 0, 3, m.pixelReplicationMode, "Pixel Replication Mode");
  io.bits(6, 3, 1, m.orthographic, "Projection Type");
  io.bits(6, 4, 1, m.reorder, "Reorder");
  io.bits(6, 5, 3, m.viewType, "View Type");
  io.f32(8, m.nearM);
  io.f32(12, m.farM);
  io.f32(16, m.leftDeg);
  io.f32(20, m.rightDeg);
  io.f32(24, m.topDeg);
  io.f32(28, m.bottomDeg);
}

// Sensor Control: CIGI ICD 3.3 / CCL CigiSensorCtrlV3.cpp (Pack and Unpack): byte 7 reserved.
template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, SensorControl>
void layout(IO& io, P& m) {
  io.u16(2, m.viewId);
  io.u8(4, m.sensorId);
  io.bits(5, 0, 1, m.sensorOn, "Sensor On/Off");
  io.bits(5, 1, 1, m.polarity, "Polarity");
  io.bits(5, 2, 1, m.lineDropoutEnable, "Line-by-Line Dropout Enable");
  io.bits(5, 3, 1, m.automaticGain, "Automatic Gain");
  io.bits(5, 4, 1, m.trackBlack, "Track White/Black");
  io.bits(5, 5, 3, m.trackMode, "Track Mode");
  io.bits(6, 0, 1, m.gateAndTargetResponse, "Response Type");
  io.f32(8, m.gain);
  io.f32(12, m.level);
  io.f32(16, m.acCoupling);
  io.f32(20, m.noise);
}

template <class IO, class P> requires std::is_same_v<std::remove_const_t<P>, StartOfFrame>
void layout(IO& io, P& m) {
  io.constantU8(2, kMajorVersion);
  io.i8(3, m.databaseNumber);
  io.u8(4, m.igStatus);
  io.bits(5, 0, 2, m.igMode, "IG Mode");
  io.bits(5, 2, 1, m.timestampValid, "Timestamp Valid");
  io.bits(5, 3, 1, m.hostDefinedEarthModel, "Earth Reference Model");
  io.constantBits(5, 4, 4, kMinorVersion);
  io.constantU16(6, kByteSwapMagic);
  io.u32(8, m.igFrameNumber);
  io.u32(12, m.timestamp);
  io.u32(16, m.lastHostFrameNumber);
}

}  // namespace skyig::protocol::cigi::detail
