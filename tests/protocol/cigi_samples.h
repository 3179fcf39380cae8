#pragma once
// One non-default instance of every CIGI packet type, for round trips and the pcap tests.
#include <vector>

#include "protocol/cigi/packets.h"

namespace skyig::protocol::cigi::test {

inline std::vector<Packet> everyPacketType() {
  IgControl ig;
  ig.databaseNumber = 3;
  ig.timestampValid = true;
  ig.extrapolationEnable = true;
  ig.hostFrameNumber = 4000000000u;
  ig.timestamp = 123456789u;
  ig.lastIgFrameNumber = 77;
  EntityControl e;
  e.entityId = 0;
  e.rollDeg = -12.5f;
  e.pitchDeg = 3.25f;
  e.yawDeg = 271.0f;
  e.latitudeDeg = 47.450239871234;
  e.longitudeDeg = 8.561983475982;
  e.altitudeM = 432.1;
  RateControl r;
  r.xRateMps = 33.0f;
  r.yawRateDegps = -3.0f;
  r.localCoordinates = true;
  CelestialSphereControl c;
  c.hour = 23;
  c.minute = 59;
  c.date = 12312025;
  c.starFieldIntensityPct = 42.5f;
  c.moonEnable = false;
  AtmosphereControl a;
  a.atmosphericModelEnable = true;
  a.globalHumidityPct = 65;
  a.visibilityRangeM = 8000.0f;
  a.airTemperatureC = -5.5f;
  a.barometricPressureHpa = 990.0f;
  EnvironmentalRegionControl er;
  er.regionId = 9;
  er.latitudeDeg = -33.9;
  er.longitudeDeg = 151.2;
  er.sizeXM = 5000.0f;
  er.sizeYM = 3000.0f;
  er.mergeTerrestrial = true;
  WeatherControl w;
  w.layerId = 2;  // cloud layer 2: a stratocumulus deck
  w.humidityPct = 95;
  w.visibilityRangeM = 300.0f;
  w.weatherEnable = true;
  w.scudEnable = true;
  w.cloudType = 9;
  w.severity = 5;
  w.scope = WeatherScope::entity;
  w.scudFrequencyPct = 12.5f;
  w.coveragePct = 62.5f;
  w.baseElevationM = 1200.0f;
  w.thicknessM = 450.0f;
  w.transitionBandM = 75.0f;
  w.horizontalWindSpeedMps = 8.5f;
  w.windDirectionDeg = 250.0f;
  ViewControl vc;
  vc.viewId = 4;
  vc.groupId = 2;
  vc.yawEnable = true;
  vc.yawDeg = -72.0f;
  vc.zOffsetM = -1.2f;
  ViewDefinition vd;
  vd.viewId = 4;
  vd.leftDeg = -36.0f;
  vd.rightDeg = 36.0f;
  vd.topDeg = 20.0f;
  vd.bottomDeg = -25.0f;
  vd.nearM = 0.1f;
  vd.farM = 1e6f;
  vd.mirrorMode = MirrorMode::both;
  vd.orthographic = true;
  SensorControl sc;
  sc.viewId = 1;
  sc.sensorId = 7;
  sc.sensorOn = true;
  sc.automaticGain = false;
  sc.trackMode = 4;
  sc.gain = 0.375f;
  sc.noise = 0.5f;
  StartOfFrame s;
  s.igFrameNumber = 99;
  s.lastHostFrameNumber = 98;
  s.hostDefinedEarthModel = true;
  s.igMode = IgMode::debug;
  return {ig, e, r, c, a, er, w, vc, vd, sc, s};
}

// A Sensor Control with every field away from its default, for the 3.3 and 4.0 layouts' tests
// (their hand-written bytes: tests/protocol/cigi_layout_test.cpp, cigi4_test.cpp).
inline SensorControl sensorControlWithEveryField() {
  SensorControl s;
  s.viewId = 3;
  s.sensorId = 2;
  s.sensorOn = true;
  s.polarity = SensorPolarity::blackHot;
  s.automaticGain = true;
  s.trackBlack = true;
  s.trackMode = 3;
  s.gateAndTargetResponse = true;
  s.gain = 0.5f;
  s.level = 0.25f;
  s.acCoupling = 1.0f;
  s.noise = 0.125f;
  return s;
}

}  // namespace skyig::protocol::cigi::test
