#include "sky/night_probe.h"

#include "physics/moon/moon_disc.h"
#include "physics/moon/moon_light.h"
#include "physics/night/night_diffuse.h"
#include "physics/stars/star_luminance.h"
#include "physics/goggle/night_spectra.h"
#include "physics/goggle/nvis_sky.h"
#include "sky/fog_state.h"
#include "sky/sky_state.h"
#include "physics/atmosphere/physical_camera.h"
#include "physics/common/units.h"

#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

namespace skyig::sky {

namespace {

double rec709Luminance(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

glm::dvec3 rec709Of(const std::optional<atmosphere::SpectralProbeLight>& light) {
  return light ? light->rec709 : glm::dvec3(0.0);
}

// The NVIS radiance of a light of `spectrum` whose Rec.709 radiance (after `t`) is `rgb`.
nvis::NvisRadiance nvisOf(const nvis::Spectrum& spectrum, const nvis::Transmittance& t, const glm::dvec3& rgb) {
  return nvis::nvisFromLuminance(spectrum, t, rec709Luminance(rgb));
}

// The day probe's sun disc (sunlight along the view) and ground (taken as lit by sunlight and
// grey, an approximation: both are dark at night) in the goggles' band.
nvis::NvisRadiance dayNvis(const atmosphere::ProbeViewResult& day, const atmosphere::ExtinctionProfile* extinction,
                           const glm::dvec3& v) {
  const nvis::Transmittance unit = nvis::unitTransmittance();
  nvis::NvisRadiance n = nvisOf(nvis::sunlitSkySpectrum(), unit, day.sky.rec709);
  if (day.sun) n += nvisOf(nvis::sunlightSpectrum(), nvis::transmittanceAlong(extinction, v), day.sun->rec709);
  if (day.ground) n += nvisOf(nvis::sunlightSpectrum(), unit, day.ground->rec709);
  return n;
}

}  // namespace

atmosphere::ProbeLight rec709Light(const glm::dvec3& rec709) { return {rec709Luminance(rec709), rec709}; }

std::vector<ProbeComponent> nightProbeComponents(const atmosphere::AtmosphereModel& model, const SkyState& state) {
  auto diffuse = nightDiffuseSky(state);
  if (!diffuse) throw std::invalid_argument("night probe: the state has no ephemeris (give a place and a time)");
  auto diffuseSky = std::make_shared<const night::NightDiffuseSky>(std::move(*diffuse));
  const atmosphere::ExtinctionProfile* extinction = state.extinction.get();
  // Each component's NVIS radiance is its own luminance along the view, weighted by its
  // spectrum through the spectral transmittance along the view (none for the skies, whose
  // light is scattered along the whole path).
  auto along = [extinction](const nvis::Spectrum& spectrum, std::function<glm::dvec3(const glm::dvec3&)> radiance) {
    return [extinction, &spectrum, radiance = std::move(radiance)](const glm::dvec3& v) {
      return nvisOf(spectrum, nvis::transmittanceAlong(extinction, v), radiance(v));
    };
  };
  auto unextinguished = [](const nvis::Spectrum& spectrum, std::function<glm::dvec3(const glm::dvec3&)> radiance) {
    return [&spectrum, radiance = std::move(radiance)](const glm::dvec3& v) {
      return nvisOf(spectrum, nvis::unitTransmittance(), radiance(v));
    };
  };
  std::vector<ProbeComponent> c;
  auto add = [&c](std::string name, std::function<glm::dvec3(const glm::dvec3&)> radiance,
                  std::function<nvis::NvisRadiance(const glm::dvec3&)> nvisRadiance) {
    c.push_back({std::move(name), std::move(radiance), std::move(nvisRadiance)});
  };
  auto moonlit = [&model, &state](const glm::dvec3& v) { return moonlitSkyRadiance(model, state, v).rec709; };
  add("moonlit_sky", moonlit, unextinguished(nvis::moonlitSkySpectrum(), moonlit));
  if (state.moonDisc) {
    auto moon = [d = state.moonDisc](const glm::dvec3& v) { return night::moonDiscRadiance(*d, v).rec709; };
    add("moon", moon, along(nvis::moonlightSpectrum(), moon));
  }
  if (state.starField) {
    const auto f = state.starField;
    add("stars_planets", [f](const glm::dvec3& v) { return night::starLuminance(*f, v).rec709; },
        [f, extinction](const glm::dvec3& v) {
          return nvis::pointSourcesNvis(*f, extinction, v, night::kStarProbeConeRadiusRad).nvis;
        });
  }
  // The night's own light through a broken deck: behind its cloud or in a gap on this view, over
  // the profile's mean (cloudFieldFactor), as the sky pass and the goggle draw it.
  const double eyeM = glm::length(atmosphere::physicalCamera(model, state.observer.heightM)) - model.parameters(0).bottom_radius;
  auto clouds = [&state, eyeM](const glm::dvec3& v) {
    return state.fog.broken() ? cloudFieldFactor(state.fog, eyeM, glm::normalize(v)) : 1.0;
  };
  auto milkyWay = [diffuseSky, clouds](const glm::dvec3& v) { return clouds(v) * night::nightDiffuseRadiance(*diffuseSky, v).milkyWay; };
  add("milky_way", milkyWay, along(nvis::integratedStarlightSpectrum(), milkyWay));
  auto zodiacal = [diffuseSky, clouds](const glm::dvec3& v) { return clouds(v) * night::nightDiffuseRadiance(*diffuseSky, v).zodiacal; };
  add("zodiacal_light", zodiacal, along(nvis::zodiacalSpectrum(), zodiacal));
  auto airglow = [diffuseSky, clouds](const glm::dvec3& v) { return clouds(v) * night::nightDiffuseRadiance(*diffuseSky, v).airglow; };
  add("airglow", airglow, along(nvis::airglowSpectrum(), airglow));
  return c;
}

std::vector<NamedProbeLight> nightProbeLights(const std::vector<ProbeComponent>& components, const glm::dvec3& viewEnu) {
  std::vector<NamedProbeLight> out;
  out.reserve(components.size());
  for (const ProbeComponent& c : components) out.push_back({c.name, rec709Light(c.radiance(viewEnu)), c.nvis(viewEnu)});
  return out;
}

std::vector<NamedProbeLight> nightProbeLights(const atmosphere::AtmosphereModel& model, const SkyState& state,
                                              const glm::dvec3& viewEnu) {
  return nightProbeLights(nightProbeComponents(model, state), viewEnu);
}

NightProbeResult nightProbe(const atmosphere::AtmosphereModel& model, const SkyState& state,
                            atmosphere::ProbeRequest request) {
  using skyig::kDegPerRad;
  request.sunZenithDeg = 90.0 - state.sunAltitude * kDegPerRad;
  request.sunAzimuthDeg = state.sunAzimuth * kDegPerRad;
  NightProbeResult out;
  out.day = atmosphere::probe(model, request);
  const std::vector<ProbeComponent> components = nightProbeComponents(model, state);
  for (const atmosphere::ProbeViewResult& day : out.day.views) {
    const glm::dvec3 v = atmosphere::localDirection(day.view.zenithDeg, day.view.azimuthDeg);
    NightProbeView night;
    // The sunlit sky is the day output's sky, under the name that pairs it with the moonlit one.
    night.lights.push_back(
        {"sunlit_sky", rec709Light(day.sky.rec709), nvisOf(nvis::sunlitSkySpectrum(), nvis::unitTransmittance(), day.sky.rec709)});
    glm::dvec3 total = day.sky.rec709 + rec709Of(day.sun) + rec709Of(day.ground);
    nvis::NvisRadiance totalNvis = dayNvis(day, state.extinction.get(), v);
    for (NamedProbeLight& l : nightProbeLights(components, v)) {
      total += l.light.rec709;
      totalNvis += l.nvis;
      night.lights.push_back(std::move(l));
    }
    night.total = rec709Light(total);
    night.totalNvis = totalNvis;
    out.views.push_back(std::move(night));
  }
  if (out.day.irradiance) {
    // The moon beside the sun: its disc after extinction, and the sky it lights (the sunlit
    // sky's irradiance lit from the moon's direction, scaled as the moonlit sky).
    const glm::dvec3 camera = atmosphere::observerPosition(model.config().medium, std::max(state.observer.heightM, 0.0));
    const glm::dvec3 moonlitSky =
        model.converter().toRec709(model.skyIrradiance(camera, glm::dvec3(0.0, 0.0, 1.0), state.moonDirection)) *
        state.moonlightScale;
    const double moonlitSkyLux = rec709Luminance(moonlitSky);
    NightProbeIrradiance e;
    e.moonLux = moonIlluminanceLux(state);
    e.moonlitSkyLux = moonlitSkyLux;
    e.moonNvis = nvis::moonIrradiance(e.moonLux, state.extinction.get(), state.moonDirection).nvis;
    e.moonlitSkyNvis = nvis::nvisFromLuminance(nvis::moonlitSkySpectrum(), nvis::unitTransmittance(), moonlitSkyLux);
    if (state.ephemeris)
      e.moonlessSky = nvis::moonlessSkyIrradiance(*state.ephemeris, state.extinction, state.starField.get()).total();
    out.irradiance = e;
  }
  out.utc = state.observer.utc;
  out.latitudeDeg = state.observer.latitudeDeg;
  out.longitudeDeg = state.observer.longitudeDeg;
  return out;
}

}  // namespace skyig::sky
