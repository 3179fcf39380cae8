#include "commands/probe_json.h"

#include <string>
#include <utility>

#include "ephemeris/time.h"
#include "physics/goggle/nvis_response.h"

namespace skyig::services {

namespace {

// Values at the probe's wavelengths, keyed by the wavelength in whole nm ("440", ...).
template <std::size_t N>
nlohmann::json byWavelength(const std::array<double, N>& values) {
  static_assert(N == atmosphere::kProbeWavelengthsNm.size());
  nlohmann::json j = nlohmann::json::object();
  for (std::size_t i = 0; i < N; ++i) j[std::to_string(static_cast<int>(atmosphere::kProbeWavelengthsNm[i]))] = values[i];
  return j;
}

nlohmann::json spectralLightJson(const atmosphere::SpectralProbeLight& light) {
  nlohmann::json j = probeLightJson(light);
  j["spectral_radiance"] = byWavelength(light.spectralRadiance);
  return j;
}

nlohmann::json optionalLightJson(const std::optional<atmosphere::SpectralProbeLight>& light) {
  return light ? spectralLightJson(*light) : nlohmann::json(nullptr);
}

// A night light with its NVIS radiance beside its luminance (sky/nvis, docs/nvis.md).
nlohmann::json nightLightJson(const atmosphere::ProbeLight& light, const sky::nvis::NvisRadiance& nvis) {
  nlohmann::json j = probeLightJson(light);
  j["nvis_a_w_m2_sr"] = nvis.a;
  j["nvis_b_w_m2_sr"] = nvis.b;
  return j;
}

}  // namespace

nlohmann::json probeLightJson(const atmosphere::ProbeLight& light) {
  return {{"luminance_cd_m2", light.luminance}, {"rgb_cd_m2", {light.rec709.r, light.rec709.g, light.rec709.b}}};
}

nlohmann::json probeJson(const atmosphere::ProbeResult& result) {
  nlohmann::json out;
  out["model"] = "physical";
  out["altitude_m"] = result.altitudeM;
  out["sun"] = {{"zenith_deg", result.sunZenithDeg}, {"azimuth_deg", result.sunAzimuthDeg}};
  out["views"] = nlohmann::json::array();
  for (const atmosphere::ProbeViewResult& v : result.views) {
    nlohmann::json view = {{"zenith_deg", v.view.zenithDeg},
                           {"azimuth_deg", v.view.azimuthDeg},
                           {"sky", spectralLightJson(v.sky)},
                           {"sun", optionalLightJson(v.sun)},
                           {"ground", optionalLightJson(v.ground)},
                           {"transmittance", byWavelength(v.transmittance)}};
    out["views"].push_back(std::move(view));
  }
  if (result.irradiance)
    out["irradiance"] = {{"direct_sun_lux", result.irradiance->directSunLux}, {"sky_lux", result.irradiance->skyLux}};
  return out;
}

nlohmann::json nightProbeJson(const sky::NightProbeResult& result) {
  nlohmann::json out = probeJson(result.day);
  for (std::size_t i = 0; i < result.views.size(); ++i) {
    nlohmann::json& view = out["views"].at(i);
    for (const sky::NamedProbeLight& l : result.views[i].lights) view[l.name] = nightLightJson(l.light, l.nvis);
    view["total"] = nightLightJson(result.views[i].total, result.views[i].totalNvis);
  }
  if (result.irradiance) {
    const sky::NightProbeIrradiance& e = *result.irradiance;
    nlohmann::json& j = out["irradiance"];
    j["moon_lux"] = e.moonLux;
    j["moonlit_sky_lux"] = e.moonlitSkyLux;
    j["moon_nvis_a_w_m2"] = e.moonNvis.a;
    j["moon_nvis_b_w_m2"] = e.moonNvis.b;
    j["moonlit_sky_nvis_a_w_m2"] = e.moonlitSkyNvis.a;
    j["moonlit_sky_nvis_b_w_m2"] = e.moonlitSkyNvis.b;
    j["moonless_sky_lux"] = e.moonlessSky.luminance;
    j["moonless_sky_nvis_a_w_m2"] = e.moonlessSky.nvis.a;
    j["moonless_sky_nvis_b_w_m2"] = e.moonlessSky.nvis.b;
  }
  // The goggles' response is a stand-in until MIL-STD-3009's table is at hand (nvis_response.h).
  out["nvis_response_provisional"] = sky::nvis::kNvisResponseProvisional;
  out["utc"] = ephemeris::formatIso8601Utc(result.utc);
  out["latitude_deg"] = result.latitudeDeg;
  out["longitude_deg"] = result.longitudeDeg;
  return out;
}

nlohmann::json libraryLightJson(const skyig::Light& light) {
  auto direct = [](const skyig::DirectLight& d) {
    return nlohmann::json{{"direction_enu", d.direction},
                          {"normal_lux", d.normalLux},
                          {"horizontal_lux", d.horizontalLux},
                          {"colour_rec709", d.colour}};
  };
  return {{"sun", direct(light.sun)},
          {"moon", direct(light.moon)},
          {"ambient_horizontal_lux", light.ambientHorizontalLux},
          {"ambient_horizontal_rec709_lux", light.ambientHorizontalRec709},
          {"sky_sh_rec709_cd_m2", light.skySh},
          {"adaptation_cd_m2", light.adaptationLuminance},
          {"adaptation_gain", light.adaptationGain}};
}

}  // namespace skyig::services
