#include "node/host/cigi_state.h"

#include "physics/weather/cloud_layer.h"

#include "protocol/cigi/date.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <variant>

namespace skyig::services {

namespace cigi = protocol::cigi;

namespace {

bool finite(double v) { return std::isfinite(v); }

// CIGI 3.3 (Entity Control, View Control): roll -180..180, pitch -90..90, yaw 0..360 degrees.
// Hosts also send yaw as -180..180, so yaw is taken in -180..360; beyond these (roll 361, yaw
// 3e38) the value is rejected and counted, never wrapped into something the host did not mean.
bool validAttitude(float yaw, float pitch, float roll) {
  return std::isfinite(yaw) && std::isfinite(pitch) && std::isfinite(roll) && yaw >= -180.0f && yaw <= 360.0f &&
         std::abs(pitch) <= 90.0f && std::abs(roll) <= 180.0f;
}

bool validOwnship(const cigi::EntityControl& e) {
  return finite(e.latitudeDeg) && std::abs(e.latitudeDeg) <= 90.0 && finite(e.longitudeDeg) &&
         std::abs(e.longitudeDeg) <= 360.0 && finite(e.altitudeM) && std::abs(e.altitudeM) < 1e7 &&
         validAttitude(e.yawDeg, e.pitchDeg, e.rollDeg);
}

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// How closely skyig follows a CIGI 4.0 host's stated seconds: the clock runs on the host's
// timestamps and is corrected only when it leaves this window around the stated instant.
constexpr double kStatedSecondsResolutionS = 1e-3;

}  // namespace

void CigiStateTracker::anchorTimestamp(std::uint32_t timestamp, Clock::time_point arrival) {
  // The clock goes on from where it stands; before anything was derived from it (no timestamp,
  // no stated time yet) it starts at zero rather than at this node's arrival instant, so nodes
  // that heard the same first message count the host's time alike.
  const bool fresh = !clock_.haveTimestamp && !clock_.clock.valid();
  anchorBaseS_ = fresh ? 0.0 : clock_.continuousAt(arrival);
  ticksSinceAnchor_ = 0;
  clock_.timestampBaseS = anchorBaseS_;
  clock_.timestampArrival = arrival;
  clock_.haveTimestamp = true;
  lastTimestamp_ = timestamp;
  sessionHasTimestamp_ = true;
  rateAnchorS_ = clock_.timestampBaseS;
  rateAnchorArrival_ = arrival;
  rate_.reset();
}

double HostClock::continuousAt(Clock::time_point t) const {
  // With host timestamps, the host's own clock (smooth, immune to network jitter); without,
  // the arrival time.
  if (haveTimestamp) return timestampBaseS + seconds(t - timestampArrival);
  return seconds(t.time_since_epoch());
}

namespace {
using Applied = CigiStateTracker::Applied;
constexpr Applied kChanged{true, 0, true}, kRejected{false, 1, true}, kIgnored{false, 0, true};

// The thinnest visibility a weather layer is given: 10 m, denser than any fog a crew flies in
// (a host's 1 mm would make an extinction single precision cannot hold).
constexpr double kSmallestLayerVisibilityM = 10.0;

// Weather Control layers 4-9 (rain, snow, sleet, hail, sand, dust), global: from the base
// elevation (MSL, the model's ground) up through the thickness, the visibility inside (0: the
// one the severity names) over the coverage (physics/weather/precipitation.h).
Applied precipitationFrom(weather::Precipitation kind, const cigi::WeatherControl& p, HostState& state) {
  std::optional<sky::FogSpec>& slot = state.precipitation[static_cast<std::size_t>(kind)];
  if (!p.weatherEnable) {
    slot = sky::FogSpec{};
    return kChanged;
  }
  if (!std::isfinite(p.baseElevationM) || !std::isfinite(p.thicknessM) || !(p.thicknessM > 0.0f) ||
      !std::isfinite(p.visibilityRangeM) || p.visibilityRangeM < 0.0f || !(p.coveragePct >= 0.0f && p.coveragePct <= 100.0f))
    return kRejected;
  const double base = std::max(0.0, static_cast<double>(p.baseElevationM));
  const double top = static_cast<double>(p.baseElevationM) + static_cast<double>(p.thicknessM);
  if (!(top > base)) {  // wholly below the ground
    slot = sky::FogSpec{};
    return kChanged;
  }
  const double visibilityM = p.visibilityRangeM > 0.0f ? std::max<double>(p.visibilityRangeM, kSmallestLayerVisibilityM) : 0.0;
  try {  // a layer the model refuses is refused and counted, the last good one kept
    slot = weather::precipitationLayer(kind, base, top, visibilityM / 1000.0, p.severity,
                                       static_cast<double>(p.coveragePct) / 100.0);
  } catch (const std::invalid_argument&) {
    return kRejected;
  }
  return kChanged;
}

// Weather Control layers 1-3, global: the cloud layer as the host gives it, from its base
// elevation (MSL, the model's ground) up through the thickness; refused whole for a bad value or
// an unknown type (CIGI's 0 "none" with the layer enabled, or 11-15 "other").
Applied cloudFrom(const cigi::WeatherControl& p, bool cigi4, HostState& state) {
  std::optional<sky::CloudLayer>& slot = state.clouds[p.layerId - 1u];
  sky::CloudLayer l;
  l.enabled = p.weatherEnable;
  if (!l.enabled) {
    slot = l;
    return kChanged;
  }
  const std::optional<sky::CloudType> type = weather::cloudTypeOfCigi(p.cloudType);
  if (!type) return kRejected;
  l.type = *type;
  l.baseM = p.baseElevationM;
  l.thicknessM = p.thicknessM;
  l.transitionM = p.transitionBandM;
  l.topTransitionM = static_cast<double>(cigi4 ? p.topTransitionBandM : p.transitionBandM);
  l.coveragePct = p.coveragePct;
  l.severity = p.severity;
  l.visibilityM = p.visibilityRangeM;
  l.scud = p.scudEnable;
  l.scudFrequencyPct = p.scudFrequencyPct;
  l.topScud = cigi4 && p.topScudEnable;
  l.topScudFrequencyPct = cigi4 ? static_cast<double>(p.topScudFrequencyPct) : 0.0;
  l.windSpeedMps = p.horizontalWindSpeedMps;
  l.windFromDeg = p.windDirectionDeg;
  try {
    weather::validate(l);
  } catch (const std::invalid_argument&) {
    return kRejected;
  }
  slot = l;
  return kChanged;
}

}  // namespace

CigiStateTracker::Applied CigiStateTracker::on(const cigi::IgControl& p, const cigi::DecodedMessage&,
                                                Clock::time_point arrival) {
  state_.hostFrame = p.hostFrameNumber;
  if (p.timestampValid) followTimestamp(p.timestamp, arrival);
  return kChanged;
}

void CigiStateTracker::followTimestamp(std::uint32_t timestamp, Clock::time_point arrival) {
  // 32-bit 10 us ticks wrap every 11.9 hours: the step is the signed difference (a wrap is a
  // small step forward, one tick back is one tick back), and bounded.
  const std::int32_t ticks = static_cast<std::int32_t>(timestamp - lastTimestamp_);
  const double step = ticks * 1e-5;
  if (!sessionHasTimestamp_ || step < -kMaxTimestampBackS || step > kMaxTimestampStepS) {
    // A session's first timestamp, or a re-based host clock: the clock goes on from where it
    // stands, so neither moves the sim clock.
    if (sessionHasTimestamp_) ++timestampJumps_;
    anchorTimestamp(timestamp, arrival);
    return;
  }
  // A small step back (jitter of the host's clock) is ignored: the host's time never runs
  // backwards, and the next step is taken from the newest timestamp.
  if (step < 0.0) return;
  ticksSinceAnchor_ += ticks;
  clock_.timestampBaseS = anchorBaseS_ + static_cast<double>(ticksSinceAnchor_) * 1e-5;
  clock_.timestampArrival = arrival;
  lastTimestamp_ = timestamp;
  if (arrival - rateAnchorArrival_ >= std::chrono::seconds(1)) {
    const double rate = (clock_.timestampBaseS - rateAnchorS_) / seconds(arrival - rateAnchorArrival_);
    rate_ = rate > 0.0 ? std::optional(rate) : std::nullopt;
    rateAnchorS_ = clock_.timestampBaseS;
    rateAnchorArrival_ = arrival;
  }
  if (rate_) messageHostTime_ = HostTime{clock_.timestampBaseS, *rate_};
}

CigiStateTracker::Applied CigiStateTracker::on(const cigi::EntityControl& p, const cigi::DecodedMessage&,
                                                Clock::time_point arrival) {
  if (p.entityId != 0) return kIgnored;  // entity 0 is the ownship; others are not skyig's
  if (!validOwnship(p)) return kRejected;
  state_.ownship = {p.latitudeDeg, p.longitudeDeg, p.altitudeM, {p.yawDeg, p.pitchDeg, p.rollDeg}};
  state_.ownshipValid = true;
  state_.ownshipTime = arrival;
  return kChanged;
}

CigiStateTracker::Applied CigiStateTracker::on(const cigi::RateControl& p, const cigi::DecodedMessage&,
                                                Clock::time_point) {
  if (p.entityId != 0 || p.applyToArticulatedPart) return kIgnored;
  const float v[6] = {p.xRateMps, p.yRateMps, p.zRateMps, p.rollRateDegps, p.pitchRateDegps, p.yawRateDegps};
  for (float x : v)
    if (!std::isfinite(x) || std::abs(x) > 1e4f) return kRejected;
  state_.rates = {true, p.localCoordinates, p.xRateMps, p.yRateMps, p.zRateMps,
                  p.rollRateDegps, p.pitchRateDegps, p.yawRateDegps};
  return kChanged;
}

CigiStateTracker::Applied CigiStateTracker::on(const cigi::CelestialSphereControl& p,
                                                const cigi::DecodedMessage& message, Clock::time_point arrival) {
  Applied a;
  // The star field applies whether or not the message carries a valid date.
  if (!std::isfinite(p.starFieldIntensityPct) || p.starFieldIntensityPct < 0.0f || p.starFieldIntensityPct > 100.0f) {
    ++a.rejected;
  } else {
    state_.starFieldIntensity = p.starFieldEnable ? static_cast<double>(p.starFieldIntensityPct) / 100.0 : 0.0;
    a.changed = true;
  }
  if (!p.dateTimeValid) return a;
  const auto date = cigi::splitDate(p.date);
  // CIGI 4.0 adds the seconds (a float, 0 <= s < 60) that 3.3 lacks.
  const bool withSeconds = message.majorVersion == 4;
  if (!date || p.hour > 23 || p.minute > 59 ||
      (withSeconds && !(std::isfinite(p.seconds) && p.seconds >= 0.0f && p.seconds < 60.0f))) {
    ++a.rejected;
    return a;
  }
  state_.timeValid = true;
  // The continuous time is taken after any IG Control of this message was applied.
  const double secondsOfDay = p.hour * 3600.0 + p.minute * 60.0 + (withSeconds ? static_cast<double>(p.seconds) : 0.0);
  clock_.clock.observe({date->year, date->month, date->day, secondsOfDay}, clock_.continuousAt(arrival),
                       withSeconds ? kStatedSecondsResolutionS : 60.0);
  a.changed = true;
  return a;
}

CigiStateTracker::Applied CigiStateTracker::on(const cigi::AtmosphereControl& p, const cigi::DecodedMessage&,
                                                Clock::time_point) {
  if (!std::isfinite(p.visibilityRangeM) || p.visibilityRangeM < 0.0f || !std::isfinite(p.airTemperatureC) ||
      !std::isfinite(p.barometricPressureHpa) || p.globalHumidityPct > 100)
    return kRejected;
  state_.visibilityM = p.visibilityRangeM;
  state_.humidityPct = p.globalHumidityPct;
  state_.temperatureC = p.airTemperatureC;
  state_.pressureHpa = p.barometricPressureHpa;
  return kChanged;
}

CigiStateTracker::Applied CigiStateTracker::on(const cigi::WeatherControl& p, const cigi::DecodedMessage& m,
                                                Clock::time_point) {
  if (p.scope != cigi::WeatherScope::global) return kIgnored;  // regions and entities: not yet
  if (p.layerId == 0) {  // ground fog: from its base elevation (MSL, the model's ground) up
    if (!p.weatherEnable) {
      state_.groundFog = sky::FogSpec{};
      return kChanged;
    }
    if (!std::isfinite(p.baseElevationM) || !std::isfinite(p.thicknessM) || !(p.thicknessM > 0.0f) ||
        !std::isfinite(p.visibilityRangeM) || !(p.visibilityRangeM > 0.0f) || !std::isfinite(p.transitionBandM) ||
        p.transitionBandM < 0.0f)
      return kRejected;
    const double base = std::max(0.0, static_cast<double>(p.baseElevationM));
    const double top = static_cast<double>(p.baseElevationM) + static_cast<double>(p.thicknessM);
    const double visibilityM = std::max<double>(p.visibilityRangeM, kSmallestLayerVisibilityM);
    state_.groundFog = sky::FogSpec{base, std::max(base, top), visibilityM / 1000.0};
    if (!(state_.groundFog->topM > state_.groundFog->bottomM)) state_.groundFog = sky::FogSpec{};  // wholly below the ground
    else state_.groundFog->transitionM = p.transitionBandM;
    return kChanged;
  }
  if (const auto kind = weather::precipitationOfLayer(p.layerId)) return precipitationFrom(*kind, p, state_);
  if (p.layerId >= 1 && p.layerId <= sky::kCloudLayers) return cloudFrom(p, m.majorVersion == 4, state_);
  // Layers 10 and up (defined by the IG): their visibility and humidity as the global weather's.
  if (!p.weatherEnable) return kIgnored;
  if (!std::isfinite(p.visibilityRangeM) || p.visibilityRangeM < 0.0f || p.humidityPct > 100) return kRejected;
  state_.visibilityM = p.visibilityRangeM;
  state_.humidityPct = p.humidityPct;
  return kChanged;
}

CigiStateTracker::Applied CigiStateTracker::on(const cigi::ViewControl& p, const cigi::DecodedMessage&,
                                                Clock::time_point) {
  if (p.entityId != 0) return kIgnored;
  if (!validAttitude(p.yawDeg, p.pitchDeg, p.rollDeg)) return kRejected;
  ViewOverride* v = view(p.viewId);
  if (!v) return kIgnored;
  if (p.yawEnable) v->yawDeg = p.yawDeg;
  if (p.pitchEnable) v->pitchDeg = p.pitchDeg;
  if (p.rollEnable) v->rollDeg = p.rollDeg;
  return kChanged;
}

CigiStateTracker::Applied CigiStateTracker::on(const cigi::ViewDefinition& p, const cigi::DecodedMessage&,
                                                Clock::time_point) {
  // CIGI's half-angles are signed (left and bottom negative for a centred view); skyig's are
  // positive towards their own side. The frustum the edits produce must stay non-empty.
  const double left = -p.leftDeg, right = p.rightDeg, up = p.topDeg, down = -p.bottomDeg;
  auto ok = [](double a) { return std::isfinite(a) && std::abs(a) < 89.5; };
  if (p.orthographic || !ok(left) || !ok(right) || !ok(up) || !ok(down)) return kRejected;
  // Each edge as it would stand: the edit, else the host's last for this view, else the channel's.
  const ViewOverride* last = state_.views.find(p.viewId);
  const sky::Frustum* channel = p.viewId < channelFrusta_.size() ? &channelFrusta_[p.viewId] : nullptr;
  auto edge = [&](bool enabled, double edited, std::optional<double> ViewOverride::*field,
                  double sky::Frustum::*configured) -> std::optional<double> {
    if (enabled) return edited;
    if (last && last->*field) return *(last->*field);
    if (channel) return channel->*configured;
    return std::nullopt;  // unknown: this pair is not checked
  };
  const auto l = edge(p.leftEnable, left, &ViewOverride::leftDeg, &sky::Frustum::leftDeg);
  const auto r = edge(p.rightEnable, right, &ViewOverride::rightDeg, &sky::Frustum::rightDeg);
  const auto u = edge(p.topEnable, up, &ViewOverride::upDeg, &sky::Frustum::upDeg);
  const auto d = edge(p.bottomEnable, down, &ViewOverride::downDeg, &sky::Frustum::downDeg);
  if ((l && r && *l + *r <= 0.1) || (u && d && *u + *d <= 0.1)) return kRejected;
  ViewOverride* v = view(p.viewId);
  if (!v) return kIgnored;
  if (p.leftEnable) v->leftDeg = left;
  if (p.rightEnable) v->rightDeg = right;
  if (p.topEnable) v->upDeg = up;
  if (p.bottomEnable) v->downDeg = down;
  return kChanged;
}

CigiStateTracker::Applied CigiStateTracker::on(const cigi::SensorControl& p, const cigi::DecodedMessage&,
                                                Clock::time_point) {
  // A view's sensor is its night-vision goggle (one per view: any Sensor ID is that goggle).
  // On/Off switches the channel between the eye's band and the goggle's class; a gain that is
  // not a fraction in [0, 1] (CIGI ICD 3.3) is counted and dropped, the switch still applies.
  // Gain 0 (what hosts send with automatic gain, the CCL's default) leaves the last gain, which
  // the goggle needs above 0.
  ViewOverride* v = view(p.viewId);
  if (!v) return kIgnored;
  v->sensorOn = p.sensorOn;
  v->automaticGain = p.automaticGain;
  Applied a{true, 0, false};  // a bad gain is dropped alone
  if (!std::isfinite(p.gain) || p.gain < 0.0f || p.gain > 1.0f) ++a.rejected;
  else if (p.gain > 0.0f) v->gain = p.gain;
  return a;
}

ViewOverride* CigiStateTracker::view(std::uint16_t viewId) {
  ViewOverride* v = state_.views.entry(viewId, maxViews_);
  if (!v) ++droppedViews_;  // beyond host.max_views: counted (NodeStats::droppedViews)
  return v;
}

int CigiStateTracker::apply(const cigi::DecodedMessage& message, Clock::time_point arrival) {
  const CigiStateTracker before = *this;  // a refused message leaves no trace
  int rejected = 0;
  bool changed = false, refused = false;
  messageHostTime_.reset();
  if (!message.packets.empty() && std::holds_alternative<cigi::IgControl>(message.packets.front()))
    state_.cigiMajorVersion = message.majorVersion;  // the node answers in the host's version
  for (const cigi::Packet& packet : message.packets) {
    // Environmental Region Control and the IG's own packets have nothing for a sky without
    // regions: the catch-all overload ignores them.
    const Applied a = std::visit([&](const auto& p) { return on(p, message, arrival); }, packet);
    changed = changed || a.changed;
    rejected += a.rejected;
    refused = refused || (a.rejected > 0 && a.refusesFrame);
  }
  if (refused) {
    *this = before;
    return rejected;
  }
  if (changed) {
    ++state_.updates;
    state_.received = arrival;
    if (const auto utc = clock_.utcAt(arrival)) {
      state_.utc = *utc;
      state_.utcTime = arrival;
    }
  }
  return rejected;
}

}  // namespace skyig::services
