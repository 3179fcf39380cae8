// The public Sky: a services::SkyWorker fed by the host's calls instead of CIGI datagrams, so a
// host embedding skyig gets the states `skyig serve` would show for the same observer and clock
// (the same ephemeris, atmosphere updates and eye adaptation), and sky::hostLight's light.
#include "skyig/sky.h"

#include "api/sky_impl.h"
#include "node/config/node_tables.h"
#include "node/config/sky_data.h"
#include "physics/analytic/analytic_sky.h"
#include "physics/atmosphere/physical_camera.h"
#include "physics/weather/cloud_layer.h"
#include "sky/client_light.h"
#include "sky/fog_state.h"
#include "physics/common/units.h"

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace skyig {

namespace {

Vec3 toVec3(const glm::dvec3& v) { return {v.x, v.y, v.z}; }
glm::dvec3 toGlm(const Vec3& v) { return {v[0], v[1], v[2]}; }

DirectLight toPublic(const sky::ClientDirectLight& l) {
  return {toVec3(l.direction), l.normalLux, l.horizontalLux, toVec3(l.colour)};
}

// The thinnest air a host may ask for: 10 m of visibility, denser than any fog a crew flies in.
constexpr double kMinVisibilityKm = 0.01;

// A number for a message (snprintf, not std::to_string(double), whose libstdc++ template would
// be exported from the library beside its API).
std::string number(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

std::string vectorText(const Vec3& v) { return "(" + number(v[0]) + ", " + number(v[1]) + ", " + number(v[2]) + ")"; }

// A value the host passed that the sky cannot use: the name and the value in the message.
void require(bool ok, const char* name, double value, const char* expected) {
  if (ok) return;
  throw Error(std::string("skyig::Sky::update: ") + name + " = " + number(value) + ": expected " + expected);
}

services::NodeConfig configOf(const Settings& settings) {
  try {
    services::NodeConfig config = settings.configFile.empty() ? services::parseNodeConfig("", "skyig's built-in defaults")
                                                              : services::loadNodeConfig(settings.configFile);
    if (!settings.model.empty() && !sky::parseSkyModel(settings.model, config.sky.model))
      throw Error("skyig::Settings::model: \"" + settings.model + "\": expected physical, preetham or cie:<type>");
    if (!settings.tables.empty()) {
      if (settings.tables != "small" && settings.tables != "medium" && settings.tables != "default")
        throw Error("skyig::Settings::tables: \"" + settings.tables + "\": expected small, medium or default");
      config.atmosphere.tables = settings.tables;
    }
    if (settings.visibilityKm > 0.0) config.atmosphere.visibilityKm = settings.visibilityKm;
    config.temporalAdaptation = settings.temporalAdaptation;
    return config;
  } catch (const services::ConfigError& e) {
    throw Error(e.what());
  }
}

}  // namespace

const char* version() { return SKYIG_VERSION; }

Vec3 irradianceFromSh(const Light& light, const Vec3& normal) {
  const glm::dvec3 n = toGlm(normal);
  const double length = glm::length(n);
  if (!std::isfinite(length) || !(length > 0.0))
    throw Error("skyig::irradianceFromSh: normal " + vectorText(normal) + ": expected a finite, non-zero vector");
  sky::ShCoefficients sh;
  for (std::size_t i = 0; i < sh.size(); ++i) sh[i] = toGlm(light.skySh[i]);
  return toVec3(sky::shIrradiance(sh, n / length));
}

Sky::Impl::Impl(const Settings& settings) : config(configOf(settings)) {
  try {
    services::loadSkyData(config);
    if (config.sky.model == sky::SkyModel::Physical) updater = services::makeAtmosphereUpdater(config);
    worker = std::make_unique<services::SkyWorker>(config, updater.get(), stats);
    worker->setHostInstantsOnly(true);
    state = *worker->step(nullptr, services::Clock::now(), /*force=*/true);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(e.what());
  }
}

Sky::Impl::~Impl() = default;

const sky::ClientLight& Sky::Impl::clientLight() const {
  if (!light) light = sky::clientLight(state, state.conditions.atmosphere.get());
  return *light;
}

Sky::Sky(const Settings& settings) : impl_(std::make_unique<Impl>(settings)) {}

const Sky::Impl& Sky::impl() const {
  if (!impl_) throw Error("skyig::Sky: used after it was moved from (assign it another Sky first)");
  return *impl_;
}
Sky::~Sky() = default;
Sky::Sky(Sky&&) noexcept = default;
Sky& Sky::operator=(Sky&&) noexcept = default;

void Sky::update(const Observer& o, double hostSeconds, const Weather& weather) {
  require(std::abs(hostSeconds) < 1.0e9, "hostSeconds", hostSeconds, "a finite time within 30 years of the clock's origin");
  require(std::abs(o.latitudeDeg) <= 90.0, "latitudeDeg", o.latitudeDeg, "-90 to 90");
  require(std::abs(o.longitudeDeg) <= 360.0, "longitudeDeg", o.longitudeDeg, "-360 to 360");
  require(o.heightM > -500.0 && o.heightM < 1.0e6, "heightM", o.heightM, "above -500 m and below 1000 km");
  require(o.utc.month >= 1 && o.utc.month <= 12, "utc.month", o.utc.month, "1 to 12");
  require(o.utc.day >= 1 && o.utc.day <= 31, "utc.day", o.utc.day, "1 to 31");
  require(o.utc.secondsOfDay >= 0.0 && o.utc.secondsOfDay < 86401.0, "utc.secondsOfDay", o.utc.secondsOfDay, "0 to 86400");
  require(o.pressureHpa > 0.0 && o.pressureHpa < 2000.0, "pressureHpa", o.pressureHpa, "0 to 2000 hPa");
  require(o.temperatureC > -100.0 && o.temperatureC < 100.0, "temperatureC", o.temperatureC, "-100 to 100 C");
  require(weather.visibilityKm == 0.0 || (weather.visibilityKm >= kMinVisibilityKm && std::isfinite(weather.visibilityKm)),
          "weather.visibilityKm", weather.visibilityKm, "0 (the configuration's) or a finite 0.01 km (10 m) and more");
  require(weather.humidityPct >= 0.0 && weather.humidityPct <= 100.0, "weather.humidityPct", weather.humidityPct, "0 to 100");

  (void)impl();  // throws for a moved-from Sky
  Impl& m = *impl_;
  // The host's call as the CIGI receiver would have published it (node/host/host_snapshot.h),
  // stamped on the host's clock: the worker steps the eye on it.
  services::HostSnapshot next = m.host;
  services::HostState& s = next.state;
  const auto received = services::Clock::time_point(
      std::chrono::duration_cast<services::Clock::duration>(std::chrono::duration<double>(hostSeconds)));
  const bool sameInstant = s.updates > 0 && received == s.received;
  ++s.updates;
  s.received = s.ownshipTime = s.utcTime = received;
  s.ownshipValid = s.timeValid = true;
  s.ownship.latitudeDeg = o.latitudeDeg;
  s.ownship.longitudeDeg = o.longitudeDeg;
  s.ownship.heightM = o.heightM;
  s.utc = {o.utc.year, o.utc.month, o.utc.day, o.utc.secondsOfDay};
  s.pressureHpa = o.pressureHpa;
  s.temperatureC = o.temperatureC;
  // No weather: HostState's defaults, which keep the configuration's atmosphere (as a host that
  // never sent an Atmosphere Control).
  const services::HostState unsaid;
  s.visibilityM = weather.visibilityKm > 0.0 ? metresFromKm(weather.visibilityKm) : unsaid.visibilityM;
  s.humidityPct = weather.visibilityKm > 0.0 ? weather.humidityPct : unsaid.humidityPct;
  next.predictor = services::OwnshipPredictor{};
  next.predictor.addSample(s.ownship, received, {});
  try {
    const bool newTables = m.worker->followAtmosphere(&next, received);
    // The same host instant again (a paused host): rebuilt for the new observer, the eye as it is.
    auto built = m.worker->step(&next, received, newTables || sameInstant);
    if (built) {
      m.state = std::move(*built);
      m.light.reset();
    }
    m.host = std::move(next);
  } catch (const std::exception& e) {
    throw Error(std::string("skyig::Sky::update: ") + e.what());
  }
}

void Sky::setClouds(const std::array<CloudLayer, 3>& layers) {
  (void)impl();  // throws for a moved-from Sky
  Impl& m = *impl_;
  std::array<std::optional<sky::CloudLayer>, sky::kCloudLayers> next{};
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const CloudLayer& l = layers[i];
    if (!l.enabled) continue;
    const std::string which = "skyig::Sky::setClouds: layer " + std::to_string(i + 1) + ": ";
    const std::optional<sky::CloudType> type = weather::parseCloudType(l.type);
    if (!type) throw Error(which + "type \"" + l.type + "\" is not a cloud type (stratus, cumulus, cirrus, ...)");
    sky::CloudLayer c;
    c.enabled = true;
    c.type = *type;
    c.baseM = l.baseM;
    c.thicknessM = l.thicknessM;
    c.coveragePct = l.coveragePct;
    c.windSpeedMps = l.windSpeedMps;
    c.windFromDeg = l.windFromDeg;
    c.severity = l.severity;
    try {
      weather::validate(c);
    } catch (const std::exception& e) {
      throw Error(which + e.what());
    }
    next[i] = c;
  }
  m.host.state.clouds = next;
}

namespace {

// The physical model of `m`'s state for a call about a point offsetEnuM from the observer;
// throws Error naming `call` under an analytic sky or for a non-finite offset.
const atmosphere::AtmosphereModel& modelForPoint(const Sky::Impl& m, const char* call, const Vec3& offsetEnuM) {
  const auto* model = m.state.conditions.atmosphere.get();
  if (!model || m.state.conditions.model != sky::SkyModel::Physical)
    throw Error(std::string("skyig::Sky::") + call + " needs the physical sky (Settings::model \"physical\")");
  for (const double x : offsetEnuM)
    if (!std::isfinite(x))
      throw Error(std::string("skyig::Sky::") + call + ": offset " + vectorText(offsetEnuM) + " m: expected finite metres");
  return *model;
}

}  // namespace

double Sky::sunThroughClouds(const Vec3& offsetEnuM) const {
  const Impl& m = impl();
  const atmosphere::AtmosphereModel* model = &modelForPoint(m, "sunThroughClouds", offsetEnuM);
  const glm::dvec3 sun = sky::enuDirection(m.state.sunAzimuth, m.state.sunAltitude);
  const double h = glm::length(atmosphere::physicalCamera(*model, m.state.observer.heightM)) - model->parameters(0).bottom_radius;
  return sky::decksTransmittanceAlong(m.state.fog, h + offsetEnuM[2], {offsetEnuM[0], offsetEnuM[1]}, sun);
}

Light Sky::light() const {
  const sky::ClientLight& h = impl().clientLight();
  Light l;
  l.sun = toPublic(h.sun);
  l.moon = toPublic(h.moon);
  l.ambientHorizontalLux = h.ambientHorizontalLux;
  l.ambientHorizontalRec709 = toVec3(h.ambientHorizontalRec709);
  for (std::size_t i = 0; i < l.skySh.size(); ++i) l.skySh[i] = toVec3(h.skySh[i]);
  l.adaptationLuminance = h.adaptationLuminance;
  l.adaptationGain = h.adaptationGain;
  return l;
}

AerialPerspective Sky::aerialPerspective(const Vec3& offsetEnuM) const {
  const Impl& m = impl();
  const atmosphere::AtmosphereModel& model = modelForPoint(m, "aerialPerspective", offsetEnuM);
  const sky::ClientAerialPerspective a = sky::clientAerialPerspective(m.state, model, toGlm(offsetEnuM));
  return {toVec3(a.transmittance), toVec3(a.inScattered)};
}

}  // namespace skyig
