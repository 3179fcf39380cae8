#include "sky/night_probe.h"

#include "sky/night/moon_disc.h"
#include "sky/night/moon_light.h"
#include "sky/night/night_diffuse.h"
#include "sky/night/star_luminance.h"
#include "sky/sky_state.h"

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

}  // namespace

atmosphere::ProbeLight rec709Light(const glm::dvec3& rec709) { return {rec709Luminance(rec709), rec709}; }

std::vector<ProbeComponent> nightProbeComponents(const atmosphere::AtmosphereModel& model, const SkyState& state) {
  auto diffuse = nightDiffuseSky(state);
  if (!diffuse) throw std::invalid_argument("night probe: the state has no ephemeris (give a place and a time)");
  auto diffuseSky = std::make_shared<const night::NightDiffuseSky>(std::move(*diffuse));
  std::vector<ProbeComponent> c;
  c.push_back({"moonlit_sky", [&model, &state](const glm::dvec3& v) { return moonlitSkyRadiance(model, state, v).rec709; }});
  if (state.moonDisc)
    c.push_back({"moon", [d = state.moonDisc](const glm::dvec3& v) { return night::moonDiscRadiance(*d, v).rec709; }});
  if (state.starField)
    c.push_back({"stars_planets", [f = state.starField](const glm::dvec3& v) { return night::starLuminance(*f, v).rec709; }});
  c.push_back({"milky_way", [diffuseSky](const glm::dvec3& v) { return night::nightDiffuseRadiance(*diffuseSky, v).milkyWay; }});
  c.push_back({"zodiacal_light", [diffuseSky](const glm::dvec3& v) { return night::nightDiffuseRadiance(*diffuseSky, v).zodiacal; }});
  c.push_back({"airglow", [diffuseSky](const glm::dvec3& v) { return night::nightDiffuseRadiance(*diffuseSky, v).airglow; }});
  return c;
}

NightProbeResult nightProbe(const atmosphere::AtmosphereModel& model, const SkyState& state,
                            atmosphere::ProbeRequest request) {
  constexpr double kDeg = 180.0 / std::numbers::pi;
  request.sunZenithDeg = 90.0 - state.sunAltitude * kDeg;
  request.sunAzimuthDeg = state.sunAzimuth * kDeg;
  NightProbeResult out;
  out.day = atmosphere::probe(model, request);
  const std::vector<ProbeComponent> components = nightProbeComponents(model, state);
  for (const atmosphere::ProbeViewResult& day : out.day.views) {
    const glm::dvec3 v = atmosphere::localDirection(day.view.zenithDeg, day.view.azimuthDeg);
    NightProbeView night;
    // The sunlit sky is the day output's sky, under the name that pairs it with the moonlit one.
    night.lights.push_back({"sunlit_sky", rec709Light(day.sky.rec709)});
    glm::dvec3 total = day.sky.rec709 + rec709Of(day.sun) + rec709Of(day.ground);
    for (const ProbeComponent& c : components) {
      const glm::dvec3 rgb = c.radiance(v);
      night.lights.push_back({c.name, rec709Light(rgb)});
      total += rgb;
    }
    night.total = rec709Light(total);
    out.views.push_back(std::move(night));
  }
  if (out.day.irradiance) {
    // The moon beside the sun: its disc after extinction, and the sky it lights (the sunlit
    // sky's irradiance lit from the moon's direction, scaled as the moonlit sky).
    const glm::dvec3 camera = atmosphere::observerPosition(model.config().medium, std::max(state.observer.heightM, 0.0));
    const glm::dvec3 moonlitSky =
        model.converter().toRec709(model.skyIrradiance(camera, glm::dvec3(0.0, 0.0, 1.0), state.moonDirection)) *
        state.moonlightScale;
    out.irradiance = NightProbeIrradiance{moonIlluminanceLux(state), rec709Luminance(moonlitSky)};
  }
  out.utc = state.observer.utc;
  out.latitudeDeg = state.observer.latitudeDeg;
  out.longitudeDeg = state.observer.longitudeDeg;
  return out;
}

}  // namespace skyig::sky
