#include "commands/ephemeris_command.h"

#include <iostream>
#include <memory>
#include <stdexcept>

#include "ephemeris/data_files.h"
#include "ephemeris/night_irradiance.h"

namespace skyig::services {

namespace {
using namespace skyig::ephemeris;

constexpr double kRadToDeg = 180.0 / kPi;

nlohmann::json bodyJson(const BodyPosition& p) {
  return {{"azimuth_deg", p.azimuthRad * kRadToDeg},
          {"altitude_deg", p.altitudeRad * kRadToDeg},
          {"altitude_refracted_deg", p.altitudeRefractedRad * kRadToDeg},
          {"distance_km", p.distanceKm},
          {"right_ascension_deg", p.rightAscensionRad * kRadToDeg},
          {"declination_deg", p.declinationRad * kRadToDeg}};
}
}  // namespace

nlohmann::json ephemerisToJson(const SkyEphemeris& sky, const std::vector<Star>& stars) {
  nlohmann::json j;
  j["tt_minus_utc_s"] = sky.time.ttMinusUtcS;
  j["ut1_minus_utc_s"] = sky.time.ut1MinusUtcS;
  j["julian_date_tt"] = sky.time.jdTt;
  j["gast_hours"] = sky.gastRad * kRadToDeg / 15.0;
  j["gmst_hours"] = sky.gmstRad * kRadToDeg / 15.0;
  j["sun"] = bodyJson(sky.sun);
  j["sun"]["angular_radius_deg"] = sky.sun.angularRadiusRad * kRadToDeg;
  j["sun"]["irradiance_w_m2"] = sky.sun.irradianceWm2;
  nlohmann::json moon = bodyJson(sky.moon);
  moon["phase_angle_deg"] = sky.moon.phaseAngleRad * kRadToDeg;
  moon["illuminated_fraction"] = sky.moon.illuminatedFraction;
  moon["bright_limb_angle_deg"] = sky.moon.brightLimbAngleRad * kRadToDeg;
  moon["angular_radius_deg"] = sky.moon.angularRadiusRad * kRadToDeg;
  moon["irradiance_w_m2"] = sky.moon.irradianceWm2;
  j["moon"] = moon;
  j["planets"] = nlohmann::json::array();
  for (const PlanetState& p : sky.planets) {
    nlohmann::json pj = bodyJson(p);
    pj["name"] = p.name;
    pj["magnitude"] = p.magnitude;
    pj["phase_angle_deg"] = p.phaseAngleRad * kRadToDeg;
    pj["illuminated_fraction"] = p.illuminatedFraction;
    pj["irradiance_w_m2"] = p.irradianceWm2;
    j["planets"].push_back(pj);
  }
  if (!stars.empty()) {
    j["stars"] = nlohmann::json::array();
    for (const Star& s : stars) {
      const BodyPosition p = starPosition(s, sky);
      nlohmann::json sj = {{"hr", s.hr},
                           {"name", s.name},
                           {"vmag", s.vmag},
                           {"azimuth_deg", p.azimuthRad * kRadToDeg},
                           {"altitude_deg", p.altitudeRad * kRadToDeg},
                           {"altitude_refracted_deg", p.altitudeRefractedRad * kRadToDeg}};
      if (s.bMinusV) {
        sj["b_minus_v"] = *s.bMinusV;
        sj["colour_temperature_k"] = colourTemperatureFromBv(*s.bMinusV);  // Wang, Ji & Zhang 2011, eq. 12
      }
      sj["irradiance_w_m2"] = irradianceFromMagnitude(s.vmag);  // Wang, Ji & Zhang 2011, eq. 11
      j["stars"].push_back(sj);
    }
  }
  return j;
}

nlohmann::json ephemerisToJson(const EphemerisRequest& r) {
  const std::optional<UtcTime> utc = parseIso8601Utc(r.utc);
  if (!utc)
    throw std::invalid_argument("--utc '" + r.utc + "' is not a valid UTC time; expected YYYY-MM-DDTHH:MM:SS[.fff]Z");
  Observer o;
  o.latitudeRad = r.latitudeDeg * kDegToRad;
  o.longitudeRad = r.longitudeDeg * kDegToRad;
  o.heightM = r.altitudeM;
  o.pressureHpa = r.pressureHpa;
  o.temperatureC = r.temperatureC;
  EphemerisOptions options;
  options.ttMinusUtcS = r.ttMinusUtcS;
  options.dut1S = r.dut1S;
  const SkyEphemeris sky = computeEphemeris(*utc, o, options);
  std::vector<Star> stars;
  if (r.stars > 0)
    stars = brightestStars(loadStarCatalogue(r.cataloguePath.empty() ? requireDataFile("bsc5.csv") : r.cataloguePath), r.stars);
  nlohmann::json j = ephemerisToJson(sky, stars);
  j["utc"] = formatIso8601Utc(*utc);
  j["observer"] = {{"latitude_deg", r.latitudeDeg},   {"longitude_deg", r.longitudeDeg},
                   {"altitude_m", r.altitudeM},       {"pressure_hpa", r.pressureHpa},
                   {"temperature_c", r.temperatureC}};
  return j;
}

void registerEphemerisCommand(CLI::App& app, int& exitCode, std::ostream& out, std::ostream& err) {
  auto request = std::make_shared<EphemerisRequest>();
  CLI::App* cmd = app.add_subcommand(
      "ephemeris", "Apparent topocentric sun, moon, planets (and brightest stars) as JSON");
  cmd->add_option("--lat", request->latitudeDeg, "Geodetic latitude, degrees north (WGS84)")->required();
  cmd->add_option("--lon", request->longitudeDeg, "Longitude, degrees east")->required();
  cmd->add_option("--alt", request->altitudeM, "Height above the WGS84 ellipsoid, metres (default 0)");
  cmd->add_option("--utc", request->utc, "UTC instant, YYYY-MM-DDTHH:MM:SS[.fff]Z, 1900-2100")->required();
  cmd->add_option("--pressure", request->pressureHpa, "Air pressure for refraction, hPa (default 1010)");
  cmd->add_option("--temperature", request->temperatureC, "Air temperature for refraction, C (default 10)");
  cmd->add_option("--tt-minus-utc", request->ttMinusUtcS, "Override TT - UTC, seconds");
  cmd->add_option("--dut1", request->dut1S, "UT1 - UTC, seconds (default 0)");
  cmd->add_option("--stars", request->stars, "Also list the N brightest stars (default 0)");
  cmd->add_option("--catalogue,--catalog", request->cataloguePath,
                  "Bright Star Catalogue CSV for --stars (default: bsc5.csv in skyig's data directory, "
                  "$SKYIG_DATA_DIR or <executable's directory>/../share/skyig; --catalog: the former spelling)");
  cmd->callback([request, &exitCode, &out, &err]() {
    try {
      out << ephemerisToJson(*request).dump(2) << '\n';
      exitCode = 0;
    } catch (const std::exception& e) {
      err << "skyig ephemeris: " << e.what() << '\n';
      exitCode = 2;
    }
  });
}

void registerEphemerisCommand(CLI::App& app, int& exitCode) { registerEphemerisCommand(app, exitCode, std::cout, std::cerr); }

}  // namespace skyig::services
