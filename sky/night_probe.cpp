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

glm::dvec3 rgbOf(const nlohmann::json& light) {
  if (light.is_null()) return glm::dvec3(0.0);
  const auto& rgb = light.at("rgb_cd_m2");
  return {rgb.at(0).get<double>(), rgb.at(1).get<double>(), rgb.at(2).get<double>()};
}

}  // namespace

nlohmann::json lightJson(const glm::dvec3& rec709) {
  return {{"luminance_cd_m2", rec709Luminance(rec709)}, {"rgb_cd_m2", {rec709.r, rec709.g, rec709.b}}};
}

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

nlohmann::json nightProbe(const atmosphere::AtmosphereModel& model, const SkyState& state,
                          atmosphere::ProbeRequest request) {
  constexpr double kDeg = 180.0 / std::numbers::pi;
  request.sun_zenith_deg = 90.0 - state.sunAltitude * kDeg;
  request.sun_azimuth_deg = state.sunAzimuth * kDeg;
  nlohmann::json out = atmosphere::probe(model, request);
  const std::vector<ProbeComponent> components = nightProbeComponents(model, state);
  for (nlohmann::json& view : out["views"]) {
    const glm::dvec3 v =
        atmosphere::localDirection(view.at("zenith_deg").get<double>(), view.at("azimuth_deg").get<double>());
    // The sunlit sky is the day output's "sky", under the name that pairs it with the moonlit one.
    view["sunlit_sky"] = lightJson(rgbOf(view.at("sky")));
    glm::dvec3 total = rgbOf(view.at("sky")) + rgbOf(view.at("sun")) + rgbOf(view.at("ground"));
    for (const ProbeComponent& c : components) {
      const glm::dvec3 rgb = c.radiance(v);
      view[c.key] = lightJson(rgb);
      total += rgb;
    }
    view["total"] = lightJson(total);
  }
  if (out.contains("irradiance")) {
    // The moon beside the sun: its disc after extinction, and the sky it lights (the sunlit
    // sky's irradiance lit from the moon's direction, scaled as the moonlit sky).
    const glm::dvec3 camera = atmosphere::observerPosition(model.config().medium, std::max(state.observer.heightM, 0.0));
    const glm::dvec3 moonlitSky =
        model.converter().toRec709(model.skyIrradiance(camera, glm::dvec3(0.0, 0.0, 1.0), state.moonDirection)) *
        state.moonlightScale;
    out["irradiance"]["moon_lux"] = moonIlluminanceLux(state);
    out["irradiance"]["moonlit_sky_lux"] = rec709Luminance(moonlitSky);
  }
  out["utc"] = ephemeris::formatIso8601Utc(state.observer.utc);
  out["latitude_deg"] = state.observer.latitudeDeg;
  out["longitude_deg"] = state.observer.longitudeDeg;
  return out;
}

}  // namespace skyig::sky
