#include "sky/sky_state.h"

#include "sky/view_sphere.h"

#include "ephemeris/ephemeris.h"
#include "physics/atmosphere/model.h"
#include "physics/common/hemisphere_grid.h"
#include "physics/moon/moon_disc.h"
#include "physics/moon/moon_light.h"
#include "physics/night/night_diffuse.h"
#include "physics/atmosphere/physical_camera.h"
#include "physics/physics.h"  // SUN_ANGULAR_RADIUS
#include "physics/common/units.h"
#include "physics/weather/fog_table.h"
#include "sky/nvis_weights.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <stdexcept>
#include <string>

namespace skyig::sky {

namespace {

using skyig::kDeg;

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
  require(std::isfinite(o.pressureHpa) && o.pressureHpa > 0.0 && o.pressureHpa < 2000.0,
          "pressure " + num(o.pressureHpa) + " hPa is outside (0, 2000)");
  require(std::isfinite(o.temperatureC) && o.temperatureC > -100.0 && o.temperatureC < 100.0,
          "temperature " + num(o.temperatureC) + " C is outside (-100, 100)");
  require(c.cieType >= 1 && c.cieType <= 15, "CIE sky type " + std::to_string(c.cieType) + " is outside 1..15");
}

// The ephemeris' observer: the place, and the air that refracts what is seen from it.
ephemeris::Observer ephemerisObserver(const ObserverState& o) {
  ephemeris::Observer where;
  where.latitudeRad = o.latitudeDeg * kDeg;
  where.longitudeRad = o.longitudeDeg * kDeg;
  where.heightM = std::min(o.heightM, 1e5);  // parallax beyond 100 km changes nothing seen
  where.pressureHpa = o.pressureHpa;
  where.temperatureC = o.temperatureC;
  return where;
}

// Stars and planets of a state: the ephemeris of the state, or of its time and place when the
// sun was overridden.
std::shared_ptr<const night::StarField> starFieldOf(const SkyState& s) {
  const SkyConditions& c = s.conditions;
  require(std::isfinite(c.starFieldIntensity) && c.starFieldIntensity >= 0.0 && c.starFieldIntensity <= 1.0,
          "star field intensity " + num(c.starFieldIntensity) + " is outside [0, 1]");
  std::optional<ephemeris::SkyEphemeris> own;
  if (!s.ephemeris) {
    own = ephemeris::computeEphemeris(s.observer.utc, ephemerisObserver(s.observer));
  }
  night::StarFieldOptions options;
  options.intensity = c.starFieldIntensity;
  options.timeS = s.observer.utc.secondsOfDay;
  night::StarField field = night::buildStarField(c.starCatalogue.get(), s.ephemeris ? *s.ephemeris : *own, *s.extinction, options);
  // Behind a broken deck's cloud a star is gone, in its gaps it shines (the extinction profile
  // weighed the deck by its coverage alone): as the sky pass draws the field.
  if (s.fog.broken() && s.conditions.atmosphere) {
    const double h = glm::length(atmosphere::physicalCamera(*s.conditions.atmosphere, s.observer.heightM)) -
                     s.conditions.atmosphere->parameters(0).bottom_radius;
    for (std::vector<night::PointSource>* sources : {&field.stars, &field.planets})
      for (night::PointSource& p : *sources) {
        const double f = cloudFieldFactor(s.fog, h, p.direction);
        p.rec709Lux *= f;
        p.illuminanceLux *= f;
      }
  }
  return std::make_shared<const night::StarField>(std::move(field));
}


// The sky pass's tables for the eye and the goggles (sky/fog_state.h, FogTables), at the height
// the renderer computes them for: the physical camera's above the ground.
FogTables fogTablesOf(const SkyState& state, const atmosphere::AtmosphereModel& model, double observerHeightM) {
  const FogState& fog = state.fog;
  FogTables t;
  t.heightM = glm::length(atmosphere::physicalCamera(model, observerHeightM)) - model.parameters(0).bottom_radius;
  // Where a deck is broken, the sky pass mixes the table with its gaps filled and the one without
  // it by its field (FogTables); the CPU's own uses (the eye, the light) weigh the gaps instead.
  const bool broken = fog.broken();
  using Table = std::shared_ptr<const std::vector<glm::vec4>>;
  const weather::AirTransmittance air = airTransmittanceFrom(model, t.heightM);
  auto tableOf = [&](const weather::FogLayers& layers, const weather::FogLayers& eye, const Table& eyeTable) {
    return eyeTable && std::memcmp(&layers, &eye, sizeof layers) == 0
               ? eyeTable
               : std::make_shared<const std::vector<glm::vec4>>(weather::fogTable(layers, t.heightM, weather::kFogTableSize, air));
  };
  const weather::FogLayers eye = clouded(fog, drawnFogLayers(fog));
  t.eye = tableOf(eye, eye, nullptr);
  t.nvisA = tableOf(clouded(fog, goggleFogLayers(state, nvis::NvisClass::A)), eye, t.eye);
  t.nvisB = tableOf(clouded(fog, goggleFogLayers(state, nvis::NvisClass::B)), eye, t.eye);
  if (broken) {
    const weather::FogLayers clearEye = withoutBrokenDecks(fog, drawnFogLayers(fog));
    t.clearEye = tableOf(clearEye, clearEye, nullptr);
    t.clearNvisA = tableOf(withoutBrokenDecks(fog, goggleFogLayers(state, nvis::NvisClass::A)), clearEye, t.clearEye);
    t.clearNvisB = tableOf(withoutBrokenDecks(fog, goggleFogLayers(state, nvis::NvisClass::B)), clearEye, t.clearEye);
  }
  return t;
}

// The sun's illuminance at the eye after the atmosphere (the model's direct irradiance at normal
// incidence, through the weather's layers as the disc is seen through them; or the analytic
// sky's disc radiance times its solid angle) and the moon's (its irradiance above the atmosphere
// times the transmittance along its apparent direction, the layers in it). Behind a fog the
// sun's veil fades with the disc: no halo round a sun the fog hides.
eye::GlareSources glareSources(const SkyState& s) {
  eye::GlareSources g{};
  eye::GlareSource& sun = g[0];
  sun.direction = enuDirection(s.sunAzimuth, s.sunApparentAltitude);
  if (s.conditions.model == SkyModel::Physical && s.conditions.atmosphere) {
    const atmosphere::AtmosphereModel& model = *s.conditions.atmosphere;
    const glm::dvec3 airless = enuDirection(s.sunAzimuth, s.sunAltitude);
    const glm::dvec3 camera = atmosphere::physicalCamera(model, s.observer.heightM);
    sun.angularRadiusRad = model.parameters(0).sun_angular_radius;
    sun.rec709Lux = glm::max(model.converter().toRec709(model.sunIrradiance(camera, airless, airless)), glm::dvec3(0.0)) *
                    fogTransmittanceToSpaceAlong(s.fog, model, s.observer.heightM, sun.direction);
  } else if (s.conditions.model != SkyModel::Physical) {
    sun.angularRadiusRad = std::acos(std::clamp(s.sky.params.cosSunRadius, -1.0, 1.0));
    // The analytic models keep the disc's radiance below the horizon; the earth hides it.
    if (s.sunApparentAltitude > -sun.angularRadiusRad)
      sun.rec709Lux = s.sky.params.sunRadiance * (2.0 * std::numbers::pi * (1.0 - s.sky.params.cosSunRadius));
  }
  if (s.moonDisc) {
    const night::MoonDisc& m = *s.moonDisc;
    eye::GlareSource& moon = g[1];
    moon.direction = m.centreSeen;
    moon.angularRadiusRad = m.angularRadiusRad;
    const glm::dvec3 t = m.extinction ? glm::max(m.extinction->rec709(std::asin(std::clamp(m.centreSeen.z, -1.0, 1.0))), glm::dvec3(0.0))
                                      : glm::dvec3(m.centreSeen.z > 0.0 ? 1.0 : 0.0);
    moon.rec709Lux = m.irradianceRec709 * t;
  }
  return g;
}

}  // namespace

namespace {

// The height a cached extinction profile is computed at: the nearest point of a fixed grid,
// 25 m apart up to 1250 m and 2 % apart above (where 2 % of the height is 25 m), so a profile
// is at most 12.5 m or 1 % off. A fixed grid rather than "within 25 m of the last one": the
// profile a state gets depends on its own height only, never on which heights the builder saw
// before, and two nodes (or a node and its replay) that skipped different host frames show the
// same frame alike to the bit.
double extinctionGridHeight(double heightM) {
  constexpr double kStepM = 25.0, kRatio = 1.02, kGeometricFromM = kStepM / (kRatio - 1.0);
  if (heightM <= kGeometricFromM) return kStepM * std::round(heightM / kStepM);
  return kGeometricFromM * std::pow(kRatio, std::round(std::log(heightM / kGeometricFromM) / std::log(kRatio)));
}

}  // namespace

std::shared_ptr<const atmosphere::ExtinctionProfile> SkyStateCaches::extinction(const atmosphere::Medium& medium,
                                                                               double heightM) {
  const double top = medium.topRadiusM - medium.bottomRadiusM;
  // Above the top nothing changes.
  const double h = std::clamp(extinctionGridHeight(std::clamp(heightM, 0.0, top - 1.0)), 0.0, top - 1.0);
  if (lastExtinction_ && lastMedium_ == medium && lastExtinction_->altitudeM() == h) return lastExtinction_;
  lastExtinction_ = std::make_shared<const atmosphere::ExtinctionProfile>(medium, h);
  lastMedium_ = medium;
  return lastExtinction_;
}

double moonIlluminanceLux(const SkyState& state) {
  return state.moonDisc ? night::moonIlluminanceLux(*state.moonDisc) : 0.0;
}

night::MoonRadiance moonlitSkyRadiance(const atmosphere::AtmosphereModel& model, const SkyState& state,
                                       const glm::dvec3& viewEnu) {
  return night::moonlitSkyRadiance(model, state.observer.heightM, state.moonDirection, state.moonlightScale, viewEnu);
}

eye::ToneCurve toneCurveFor(const SkyState& state, const DisplayParams& display) {
  if (display.toneOperator != ToneOperator::Histogram) return {};
  for (const auto& [d, curve] : state.toneCurves)
    if (d == display) return curve;
  // The display's black is its ambient luminance, at least a thousandth of its white (no
  // projector in a lit room does better).
  const double black = std::max(display.ambientLuminance, 1e-3 * display.maxLuminance);
  return eye::histogramAdjustment(state.histogram,
                                  {black, display.ambientLuminance + display.maxLuminance, display.viewerAdaptationLuminance},
                                  state.adaptationGain);
}

void mapForDisplays(SkyState& state, const std::vector<DisplayParams>& displays) {
  state.toneCurves.clear();
  for (const DisplayParams& d : displays) {
    if (d.toneOperator != ToneOperator::Histogram) continue;
    bool seen = false;
    for (const auto& [e, curve] : state.toneCurves) seen = seen || e == d;
    if (!seen) state.toneCurves.emplace_back(d, toneCurveFor(state, d));
  }
  if (!state.viewLight) return;
  state.shown = shownLayers(*state.viewLight, displays, state.toneCurves);
  double brightest = 0.0;
  if (state.starField)
    for (const auto* list : {&state.starField->stars, &state.starField->planets})
      for (const night::PointSource& p : *list) brightest = std::max(brightest, p.illuminanceLux);
  state.shown.pointSources = pointSourcesSeen(*state.viewLight, brightest);
  state.shown.pointSourceFloorLux = faintestPointSourceSeenLux(*state.viewLight);
}

std::optional<night::NightDiffuseSky> nightDiffuseSky(const SkyState& state, bool withMilkyWay) {
  if (!state.ephemeris) return std::nullopt;
  return night::makeNightDiffuseSky(*state.ephemeris, state.extinction, withMilkyWay);
}

SkyState buildSkyState(const ObserverState& observer, const SkyConditions& conditions,
                       const std::optional<SunOverride>& sun, SkyStateCaches* caches) {
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
    // The override places the true sun, as the ephemeris does: the disc is seen lifted by the
    // refraction of the observer's air.
    s.sunApparentAltitude =
        s.sunAltitude + ephemeris::refractionSaemundsson(s.sunAltitude, observer.pressureHpa, observer.temperatureC);
  } else {
    const ephemeris::Observer where = ephemerisObserver(observer);
    s.ephemeris = caches ? caches->ephemeris.compute(observer.utc, where) : ephemeris::computeEphemeris(observer.utc, where);
    s.sunAzimuth = s.ephemeris->sun.azimuthRad;
    s.sunAltitude = s.ephemeris->sun.altitudeRad;
    s.sunApparentAltitude = s.ephemeris->sun.altitudeRefractedRad;
    s.conditions.sunDistanceAu = s.ephemeris->sun.distanceKm / 149597870.7;
    // The moon lights the sky as a second sun (Jensen et al. 2001), scaled by its irradiance.
    s.moonDirection = enuDirection(s.ephemeris->moon.azimuthRad, s.ephemeris->moon.altitudeRad);
    s.moonlightScale = night::moonlightScale(*s.ephemeris);
  }
  const ephemeris::RefractionExpansion r = ephemeris::refractionExpansion(
      s.sunApparentAltitude, s.sunAltitude, shader::SUN_ANGULAR_RADIUS, observer.pressureHpa, observer.temperatureC);
  s.sunRefraction = {r.centreRad, r.refraction, r.slope, r.halfCurvature};
  if (s.conditions.model == SkyModel::Physical)
    require(s.conditions.atmosphere != nullptr, "the physical sky model needs its precomputed atmosphere");
  const atmosphere::Medium medium = s.conditions.atmosphere ? s.conditions.atmosphere->config().medium : atmosphere::Medium{};
  SkyStateCaches own;
  s.extinction = (caches ? *caches : own).extinction(medium, observer.heightM);
  if (s.conditions.model == SkyModel::Physical) {
    s.fog = makeFogState(*s.conditions.atmosphere, s.conditions,
                         enuDirection(s.sunAzimuth, s.sunAltitude), s.moonDirection, s.moonlightScale);
    // The decks' fields on the host's clock: seconds since J2000 (UTC), so every node and a
    // replay place them alike.
    const double timeS = (ephemeris::julianDayAt0h(observer.utc.year, observer.utc.month, observer.utc.day) - 2451545.0) * 86400.0 +
                         observer.utc.secondsOfDay;
    s.fog.cover = cloudCoversOf(s.conditions, s.conditions.atmosphere->parameters(0).bottom_radius, observer.latitudeDeg,
                                observer.longitudeDeg, timeS);
    // What comes from beyond the air (moon, planets, stars, the night's light) through the fog too.
    auto throughFog = [&](double e) {
      return fogTransmittanceToSpace(s.fog, *s.conditions.atmosphere, observer.heightM, e);
    };
    if (s.fog.any()) {
      s.extinction = std::make_shared<const atmosphere::ExtinctionProfile>(s.extinction->dimmedBy(throughFog));
      s.fog.tables = fogTablesOf(s, *s.conditions.atmosphere, observer.heightM);
    }
  }
  s.starField = starFieldOf(s);
  if (s.ephemeris) {
    night::MoonDisc moon = night::makeMoonDisc(night::moonPlacement(*s.ephemeris), s.extinction);
    if (s.fog.broken() && s.conditions.atmosphere) {
      // Behind a cloud of a broken deck, or in a gap: the disc, its light on the ground and its
      // glare (what its irradiance lights) as the sky pass's field has it there.
      const double h = glm::length(atmosphere::physicalCamera(*s.conditions.atmosphere, s.observer.heightM)) -
                       s.conditions.atmosphere->parameters(0).bottom_radius;
      const double f = cloudFieldFactor(s.fog, h, moon.centreSeen);
      moon.sunlitScale *= f;
      moon.earthshineScale *= f;
      moon.irradianceRec709 *= f;
    }
    s.moonDisc = std::make_shared<const night::MoonDisc>(std::move(moon));
    const double albedo = s.conditions.atmosphere ? medium.groundAlbedo : s.conditions.groundAlbedo;
    const glm::dvec3 e = night::nightDiffuseIlluminance(*s.ephemeris, s.extinction) +
                         (s.starField ? night::horizontalIlluminance(*s.starField) : glm::dvec3(0.0));
    s.nightGroundRadiance = albedo / std::numbers::pi * e;
  }
  if (s.conditions.model != SkyModel::Physical)
    s.sky = makeAnalyticSky(s.conditions, s.sunAzimuth, s.sunAltitude, s.sunApparentAltitude);
  s.glare = glareSources(s);
  // The eye adapts to what it sees over the whole view sphere: sky and terrain, sunlit and
  // moonlit, with the night's own light (sky/view_sphere.h); its log-mean is the scene's level.
  const ViewSphere sphere = viewSphere(s);
  s.histogram = sphere.histogram;
  s.sceneLuminance = s.worldAdaptationLuminance = sphere.meanLuminance;
  s.viewLight = sphere.cells;
  return s;
}

}  // namespace skyig::sky
