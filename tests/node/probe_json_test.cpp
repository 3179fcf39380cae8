// The JSON of `skyig probe` (commands/probe_json.h): the probe's values under their
// documented keys, nothing computed on the way.
#include "commands/probe_json.h"

#include "physics/goggle/nvis_response.h"

#include <gtest/gtest.h>

#include <array>

namespace skyig::services {
namespace {

atmosphere::SpectralProbeLight spectral(double base) {
  atmosphere::SpectralProbeLight l;
  l.luminance = base;
  l.rec709 = {base + 1.0, base + 2.0, base + 3.0};
  l.spectralRadiance = {base + 4.0, base + 5.0, base + 6.0};
  return l;
}

atmosphere::ProbeResult dayResult() {
  atmosphere::ProbeResult r;
  r.altitudeM = 12.5;
  r.sunZenithDeg = 30.0;
  r.sunAzimuthDeg = 180.0;
  atmosphere::ProbeViewResult up;
  up.view = {0.0, 10.0};
  up.sky = spectral(100.0);
  up.transmittance = {0.7, 0.8, 0.9};
  atmosphere::ProbeViewResult down;
  down.view = {120.0, 270.0};
  down.sky = spectral(200.0);
  down.sun = spectral(300.0);
  down.ground = spectral(400.0);
  down.transmittance = {1.0, 1.0, 1.0};
  r.views = {up, down};
  r.irradiance = atmosphere::ProbeIrradiance{1000.0, 200.0};
  return r;
}

TEST(ProbeJson, DayKeysAndValues) {
  const nlohmann::json expected = nlohmann::json::parse(R"({
    "model": "physical", "altitude_m": 12.5, "sun": {"zenith_deg": 30.0, "azimuth_deg": 180.0},
    "irradiance": {"direct_sun_lux": 1000.0, "sky_lux": 200.0},
    "views": [
      {"zenith_deg": 0.0, "azimuth_deg": 10.0,
       "sky": {"luminance_cd_m2": 100.0, "rgb_cd_m2": [101.0, 102.0, 103.0],
               "spectral_radiance": {"440": 104.0, "550": 105.0, "680": 106.0}},
       "sun": null, "ground": null, "transmittance": {"440": 0.7, "550": 0.8, "680": 0.9}},
      {"zenith_deg": 120.0, "azimuth_deg": 270.0,
       "sky": {"luminance_cd_m2": 200.0, "rgb_cd_m2": [201.0, 202.0, 203.0],
               "spectral_radiance": {"440": 204.0, "550": 205.0, "680": 206.0}},
       "sun": {"luminance_cd_m2": 300.0, "rgb_cd_m2": [301.0, 302.0, 303.0],
               "spectral_radiance": {"440": 304.0, "550": 305.0, "680": 306.0}},
       "ground": {"luminance_cd_m2": 400.0, "rgb_cd_m2": [401.0, 402.0, 403.0],
                  "spectral_radiance": {"440": 404.0, "550": 405.0, "680": 406.0}},
       "transmittance": {"440": 1.0, "550": 1.0, "680": 1.0}}
    ]})");
  EXPECT_EQ(probeJson(dayResult()), expected) << probeJson(dayResult()).dump(2);
  atmosphere::ProbeResult noIrradiance = dayResult();
  noIrradiance.irradiance.reset();
  EXPECT_FALSE(probeJson(noIrradiance).contains("irradiance"));
}

// Every night light carries its class A and B NVIS radiance beside its luminance (docs/nvis.md).
TEST(ProbeJson, NightAddsTheLightsTheirTotalAndThePlace) {
  sky::NightProbeResult r;
  r.day = dayResult();
  for (double base : {1.0, 2.0}) {
    sky::NightProbeView v;
    v.lights = {{"sunlit_sky", {base, {base, 0.0, 0.0}}, {3.0 * base, 4.0 * base}},
                {"airglow", {10.0 * base, {0.0, base, 0.0}}, {5.0 * base, 6.0 * base}}};
    v.total = {100.0 * base, {base, base, 0.0}};
    v.totalNvis = {7.0 * base, 8.0 * base};
    r.views.push_back(v);
  }
  sky::NightProbeIrradiance e;
  e.moonLux = 0.1;
  e.moonlitSkyLux = 0.01;
  e.moonNvis = {1e-3, 2e-3};
  e.moonlitSkyNvis = {3e-3, 4e-3};
  e.moonlessSky = {1e-3, {5e-3, 6e-3}};
  r.irradiance = e;
  r.utc = {2026, 1, 18, 19 * 3600.0};
  r.latitudeDeg = 47.26;
  r.longitudeDeg = 11.34;
  const nlohmann::json j = nightProbeJson(r);

  nlohmann::json expected = probeJson(r.day);
  auto light = [](double l, std::array<double, 3> rgb, double a, double b) {
    return nlohmann::json{{"luminance_cd_m2", l}, {"rgb_cd_m2", rgb}, {"nvis_a_w_m2_sr", a}, {"nvis_b_w_m2_sr", b}};
  };
  expected["views"][0]["sunlit_sky"] = light(1.0, {1.0, 0.0, 0.0}, 3.0, 4.0);
  expected["views"][0]["airglow"] = light(10.0, {0.0, 1.0, 0.0}, 5.0, 6.0);
  expected["views"][0]["total"] = light(100.0, {1.0, 1.0, 0.0}, 7.0, 8.0);
  expected["views"][1]["sunlit_sky"] = light(2.0, {2.0, 0.0, 0.0}, 6.0, 8.0);
  expected["views"][1]["airglow"] = light(20.0, {0.0, 2.0, 0.0}, 10.0, 12.0);
  expected["views"][1]["total"] = light(200.0, {2.0, 2.0, 0.0}, 14.0, 16.0);
  expected["irradiance"]["moon_lux"] = 0.1;
  expected["irradiance"]["moonlit_sky_lux"] = 0.01;
  expected["irradiance"]["moon_nvis_a_w_m2"] = 1e-3;
  expected["irradiance"]["moon_nvis_b_w_m2"] = 2e-3;
  expected["irradiance"]["moonlit_sky_nvis_a_w_m2"] = 3e-3;
  expected["irradiance"]["moonlit_sky_nvis_b_w_m2"] = 4e-3;
  expected["irradiance"]["moonless_sky_lux"] = 1e-3;
  expected["irradiance"]["moonless_sky_nvis_a_w_m2"] = 5e-3;
  expected["irradiance"]["moonless_sky_nvis_b_w_m2"] = 6e-3;
  expected["nvis_response_provisional"] = sky::nvis::kNvisResponseProvisional;
  expected["utc"] = "2026-01-18T19:00:00.000Z";
  expected["latitude_deg"] = 47.26;
  expected["longitude_deg"] = 11.34;
  EXPECT_EQ(j, expected) << j.dump(2);
}

}  // namespace
}  // namespace skyig::services
