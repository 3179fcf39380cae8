#include "sky/sky_state.h"

#include "ephemeris/ephemeris.h"
#include "sky/atmosphere/model.h"
#include "sky/common/hemisphere_grid.h"
#include "sky/night/moon_disc.h"
#include "sky/night/moon_light.h"
#include "sky/night/night_diffuse.h"
#include "sky/atmosphere/physical_camera.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>

namespace skyig::sky {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

std::string num(double v) { return std::to_string(v); }

void validate(const ObserverState& o, const SkyConditions& c) {
  require(std::isfinite(o.latitudeDeg) && std::abs(o.latitudeDeg) <= 90.0,
          "latitude " + num(o.latitudeDeg) + " deg is outside [-90, 90]");
  require(std::isfinite(o.longitudeDeg) && std::abs(o.longitudeDeg) <= 360.0,
          "longitude " + num(o.longitudeDeg) + " deg is outside [-360, 360]");
  require(std::isfinite(o.heightM) && o.heightM > -500.0 && o.heightM < 1e6,
          "height " + num(o.heightM) + " m is outside (-500, 1e6)");
  require(std::isfinite(o.attitude.yawDeg) && std::isfinite(o.attitude.pitchDeg) &&
              std::isfinite(o.attitude.rollDeg),
          "attitude has a non-finite angle");
  const std::string dateError = ephemeris::validate(o.utc);
  require(dateError.empty(), "UTC time: " + dateError);
  require(o.utc.year >= 1900 && o.utc.year <= 2100,
          "year " + std::to_string(o.utc.year) + " is outside the ephemeris' 1900-2100");
  require(std::isfinite(c.turbidity) && c.turbidity >= 1.7 && c.turbidity <= 10.0,
          "turbidity " + num(c.turbidity) + " is outside [1.7, 10]");
  require(std::isfinite(c.groundAlbedo) && c.groundAlbedo >= 0.0 && c.groundAlbedo <= 1.0,
          "ground albedo " + num(c.groundAlbedo) + " is outside [0, 1]");
  require(c.cieType >= 1 && c.cieType <= 15, "CIE sky type " + std::to_string(c.cieType) + " is outside 1..15");
}

// The physical sky's mean luminance over the upper hemisphere (midpoint rule in cos theta and
// azimuth, 12 x 24: the adaptation level varies slowly, and this runs per state on the CPU).
double physicalMeanSkyLuminance(const atmosphere::AtmosphereModel& model, double heightM, const glm::dvec3& sun) {
  constexpr int kMu = 12, kPhi = 24;
  const glm::dvec3 camera = physicalCamera(model, heightM);
  double sum = 0.0;
  forEachHemisphereDirection(kMu, kPhi, [&](const glm::dvec3& view) {
    sum += model.converter().luminance(model.skyRadiance(camera, view, sun));
  });
  return sum / (kMu * kPhi);
}

// The extinction profile costs tens of milliseconds: states reuse the last one while the
// observer stays within max(25 m, 2%) of its altitude and the medium is unchanged (a climbing
// helicopter rebuilds it every few seconds, on the worker, never on the render thread).
std::shared_ptr<const atmosphere::ExtinctionProfile> sharedExtinction(const atmosphere::Medium& medium,
                                                                      double heightM) {
  static std::mutex mutex;
  static std::shared_ptr<const atmosphere::ExtinctionProfile> last;
  static atmosphere::Medium lastMedium;
  const double top = medium.topRadiusM - medium.bottomRadiusM;
  const double h = std::clamp(heightM, 0.0, top - 1.0);  // above the top nothing changes
  std::lock_guard lock(mutex);
  if (last && lastMedium == medium && std::abs(last->altitudeM() - h) <= std::max(25.0, 0.02 * h)) return last;
  last = std::make_shared<const atmosphere::ExtinctionProfile>(medium, h);
  lastMedium = medium;
  return last;
}

// Stars and planets of a state: the ephemeris of the state, or of its time and place when the
// sun was overridden.
std::shared_ptr<const night::StarField> starFieldOf(const SkyState& s) {
  const SkyConditions& c = s.conditions;
  require(std::isfinite(c.starFieldIntensity) && c.starFieldIntensity >= 0.0 && c.starFieldIntensity <= 1.0,
          "star field intensity " + num(c.starFieldIntensity) + " is outside [0, 1]");
  std::optional<ephemeris::SkyEphemeris> own;
  if (!s.ephemeris) {
    ephemeris::Observer where;
    where.latitudeRad = s.observer.latitudeDeg * kDeg;
    where.longitudeRad = s.observer.longitudeDeg * kDeg;
    where.heightM = std::min(s.observer.heightM, 1e5);
    own = ephemeris::computeEphemeris(s.observer.utc, where);
  }
  night::StarFieldOptions options;
  options.intensity = c.starFieldIntensity;
  options.timeS = s.observer.utc.secondsOfDay;
  return std::make_shared<const night::StarField>(
      night::buildStarField(c.starCatalogue.get(), s.ephemeris ? *s.ephemeris : *own, *s.extinction, options));
}

double meanNightLuminance(const SkyState& s) {
  return s.ephemeris ? night::meanNightDiffuseLuminance(*s.ephemeris, s.extinction) : 0.0;
}

}  // namespace

double moonIlluminanceLux(const SkyState& state) {
  return state.moonDisc ? night::moonIlluminanceLux(*state.moonDisc) : 0.0;
}

night::MoonRadiance moonlitSkyRadiance(const atmosphere::AtmosphereModel& model, const SkyState& state,
                                       const glm::dvec3& viewEnu) {
  return night::moonlitSkyRadiance(model, state.observer.heightM, state.moonDirection, state.moonlightScale, viewEnu);
}

std::optional<night::NightDiffuseSky> nightDiffuseSky(const SkyState& state) {
  if (!state.ephemeris) return std::nullopt;
  return night::makeNightDiffuseSky(*state.ephemeris, state.extinction);
}

SkyState buildSkyState(const ObserverState& observer, const SkyConditions& conditions,
                       const std::optional<SunOverride>& sun, ephemeris::EphemerisCache* cache) {
  validate(observer, conditions);
  SkyState s;
  s.observer = observer;
  s.conditions = conditions;
  if (sun) {
    require(std::isfinite(sun->azimuthDeg) && std::isfinite(sun->altitudeDeg) &&
                std::abs(sun->altitudeDeg) <= 90.0,
            "sun altitude " + num(sun->altitudeDeg) + " deg is outside [-90, 90]");
    s.sunAzimuth = sun->azimuthDeg * kDeg;
    s.sunAltitude = sun->altitudeDeg * kDeg;
    s.sunApparentAltitude = s.sunAltitude;
  } else {
    ephemeris::Observer where;
    where.latitudeRad = observer.latitudeDeg * kDeg;
    where.longitudeRad = observer.longitudeDeg * kDeg;
    where.heightM = std::min(observer.heightM, 1e5);  // parallax beyond 100 km changes nothing seen
    s.ephemeris = cache ? cache->compute(observer.utc, where) : ephemeris::computeEphemeris(observer.utc, where);
    s.sunAzimuth = s.ephemeris->sun.azimuthRad;
    s.sunAltitude = s.ephemeris->sun.altitudeRad;
    s.sunApparentAltitude = s.ephemeris->sun.altitudeRefractedRad;
    s.conditions.sunDistanceAu = s.ephemeris->sun.distanceKm / 149597870.7;
    // The moon lights the sky as a second sun (Jensen et al. 2001), scaled by its irradiance.
    s.moonDirection = enuDirection(s.ephemeris->moon.azimuthRad, s.ephemeris->moon.altitudeRad);
    s.moonlightScale = night::moonlightScale(*s.ephemeris);
  }
  if (s.conditions.model == SkyModel::Physical)
    require(s.conditions.atmosphere != nullptr, "the physical sky model needs its precomputed atmosphere");
  s.extinction = sharedExtinction(s.conditions.atmosphere ? s.conditions.atmosphere->config().medium
                                                          : atmosphere::Medium{},
                                  observer.heightM);
  s.starField = starFieldOf(s);
  if (s.ephemeris)
    s.moonDisc = std::make_shared<const night::MoonDisc>(night::makeMoonDisc(night::moonPlacement(*s.ephemeris), s.extinction));
  if (s.conditions.model == SkyModel::Physical) {
    s.adaptationLuminance = physicalMeanSkyLuminance(*s.conditions.atmosphere, observer.heightM,
                                                     enuDirection(s.sunAzimuth, s.sunAltitude));
    s.adaptationLuminance += meanNightLuminance(s);  // the night's own light
    return s;
  }
  s.sky = makeAnalyticSky(s.conditions, s.sunAzimuth, s.sunAltitude, s.sunApparentAltitude);
  // The eye adapts to the sky it sees: the solid-angle mean luminance of the upper hemisphere.
  s.adaptationLuminance = s.sky.lighting.meanSkyLuminance;
  s.adaptationLuminance += meanNightLuminance(s);  // the night's own light
  return s;
}

}  // namespace skyig::sky
