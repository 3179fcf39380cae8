#include "commands/common_options.h"

#include "physics/weather/cloud_layer.h"

#include "ephemeris/time.h"
#include "physics/atmosphere/conditions.h"

#include <cstdio>

namespace skyig::services {

void SkyOptions::add(CLI::App& c) {
  c.add_option("--config", configPath, "Node configuration (TOML); the embedded defaults without it")
      ->check(CLI::ExistingFile);
  c.add_option("--lat", lat, "Latitude, degrees north (WGS84)")->check(CLI::Range(-90.0, 90.0));
  c.add_option("--lon", lon, "Longitude, degrees east")->check(CLI::Range(-180.0, 360.0));
  c.add_option("--alt", alt, "Height above the WGS84 ellipsoid, metres")->check(CLI::Range(-400.0, 1e6));
  c.add_option("--yaw", yaw, "Ownship true heading, degrees clockwise from north")->check(CLI::Range(-360.0, 360.0));
  c.add_option("--pitch", pitch, "Ownship pitch, degrees, nose up positive")->check(CLI::Range(-90.0, 90.0));
  c.add_option("--roll", roll, "Ownship roll, degrees, right wing down positive")->check(CLI::Range(-180.0, 180.0));
  c.add_option("--utc", utc, "UTC date and time, e.g. 2026-06-21T19:30:00Z");
  c.add_option("--sky-model", skyModel, "Sky model: preetham | cie | physical")
      ->check(CLI::IsMember({"preetham", "cie", "physical"}));
  c.add_option("--cie-type", cieType, "CIE standard general sky type, 1 (overcast) .. 15")->check(CLI::Range(1, 15));
  c.add_option("--turbidity", turbidity, "Atmospheric turbidity (Preetham), 1.7 .. 10")->check(CLI::Range(1.7, 10.0));
  c.add_option("--ground-albedo", groundAlbedo, "Ground albedo, 0 .. 1")->check(CLI::Range(0.0, 1.0));
  c.add_option("--visibility", visibilityKm,
               "Physical sky: visibility, km (Koschmieder; haze), 0.05 .. 1000 (past about 288: clean air)")
      ->check(CLI::Range(atmosphere::kSmallestVisibilityKm, atmosphere::kLargestVisibilityKm));
  c.add_option("--aerosol", aerosol,
               "Physical sky: the aerosol, an OPAC type or Bruneton's (" + std::string(atmosphere::aerosolTypeNames()) +
                   "); its standard amount unless --visibility says")
      ->check([](const std::string& name) {
        return atmosphere::parseAerosolType(name) ? std::string()
                                                  : "expected one of " + std::string(atmosphere::aerosolTypeNames());
      });
  c.add_option("--fog-visibility", fogVisibilityKm, "Physical sky: a ground fog of this visibility inside, km (0: none)")
      ->check(CLI::Range(0.0, atmosphere::kLargestVisibilityKm));
  c.add_option("--fog-top", fogTopM, "The ground fog's top above the ground, metres (default 200)")->check(CLI::Range(0.0, 20000.0));
  c.add_option("--fog-bottom", fogBottomM, "The ground fog's bottom above the ground, metres (default 0)")
      ->check(CLI::Range(0.0, 20000.0));
  c.add_option("--fog-transition", fogTransitionM,
               "The band over which the ground fog's top fades to clear air, metres (default 0: a hard top)")
      ->check(CLI::Range(0.0, 20000.0));
  c.add_option("--precipitation", precipitation, "Physical sky: precipitation or dust from the ground up: none | rain | snow | sleet | hail | sand | dust")
      ->check(CLI::IsMember({"none", "rain", "snow", "sleet", "hail", "sand", "dust"}));
  c.add_option("--precipitation-severity", precipitationSeverity, "Its severity, 0 (least) .. 5 (CIGI's; default 2)")
      ->check(CLI::Range(0, 5));
  c.add_option("--precipitation-visibility", precipitationVisibilityKm, "The visibility inside it, km (default: the severity's)")
      ->check(CLI::Range(0.0, atmosphere::kLargestVisibilityKm));
  c.add_option("--precipitation-top", precipitationTopM, "Its top above the ground, metres (default 1500)")
      ->check(CLI::Range(1.0, 20000.0));
  c.add_option("--precipitation-coverage", precipitationCoveragePct, "The share of the sky it covers, percent (default 100)")
      ->check(CLI::Range(0.0, 100.0));
  c.add_option("--cloud", cloud,
               "Cloud layer 1 as TYPE:BASE:THICKNESS[:COVERAGE[:WIND:FROM]] (m above the ground, %, m/s, degrees it blows from), "
               "e.g. stratus:300:400:100; "
               "drawn and recorded with the frame");
  c.add_option("--sun-azimuth", sunAzimuth, "Override the sun's azimuth, degrees from north through east")
      ->check(CLI::Range(-360.0, 360.0));
  c.add_option("--sun-elevation", sunElevation, "Override the sun's true (airless) elevation, degrees; its disc is seen lifted by refraction")->check(CLI::Range(-90.0, 90.0));
}

NodeConfig SkyOptions::resolve() const {
  NodeConfig config = configPath.empty() ? NodeConfig{} : loadNodeConfig(configPath);
  sky::ObserverState& o = config.observer;
  if (lat) o.latitudeDeg = *lat;
  if (lon) o.longitudeDeg = *lon;
  if (alt) o.heightM = *alt;
  if (yaw) o.attitude.yawDeg = *yaw;
  if (pitch) o.attitude.pitchDeg = *pitch;
  if (roll) o.attitude.rollDeg = *roll;
  if (utc) {
    const auto t = ephemeris::parseIso8601Utc(*utc);
    if (!t) throw ConfigError("--utc: expected a UTC time like 2026-06-21T19:30:00Z, got \"" + *utc + "\"");
    o.utc = *t;
  }
  if (skyModel) sky::parseSkyModel(*skyModel, config.sky.model);
  if (cieType) {
    config.sky.cieType = *cieType;
    if (!skyModel) config.sky.model = sky::SkyModel::Cie;  // a CIE type implies the CIE model
  }
  if (turbidity) config.sky.turbidity = *turbidity;
  if (groundAlbedo) config.sky.groundAlbedo = *groundAlbedo;
  if (visibilityKm) config.atmosphere.visibilityKm = *visibilityKm;
  if (aerosol) {
    atmosphere::Medium& m = config.atmosphere.medium;
    m = atmosphere::withStandardAerosol(m, *atmosphere::parseAerosolType(*aerosol), m.aerosolHumidity);
  }
  if (fogVisibilityKm || fogTopM || fogBottomM || fogTransitionM) {
    sky::FogSpec& f = config.sky.fog;
    if (fogVisibilityKm) f.visibilityKm = *fogVisibilityKm;
    if (fogBottomM) f.bottomM = *fogBottomM;
    if (fogTopM) f.topM = *fogTopM;
    if (fogTransitionM) f.transitionM = *fogTransitionM;
    else if (f.topM <= f.bottomM) f.topM = f.bottomM + 200.0;
    if (f.visibilityKm > 0.0 && !(f.topM > f.bottomM))
      throw ConfigError("--fog-top " + std::to_string(f.topM) + " m: expected a top above the fog's bottom (" +
                        std::to_string(f.bottomM) + " m)");
  }
  if (precipitation || precipitationSeverity || precipitationVisibilityKm || precipitationTopM || precipitationCoveragePct) {
    weather::PrecipitationSettings& p = config.precipitation;
    if (precipitation) p.kind = weather::parsePrecipitation(*precipitation);  // "none": none
    if (precipitationSeverity) p.severity = *precipitationSeverity;
    if (precipitationVisibilityKm) p.visibilityKm = *precipitationVisibilityKm;
    if (precipitationTopM) p.topM = *precipitationTopM;
    if (precipitationCoveragePct) p.coveragePct = *precipitationCoveragePct;
    config.sky.precipitation = weather::precipitationLayer(p);
  }
  if (cloud) {
    try {
      config.sky.clouds[0] = weather::parseCloudSpec(*cloud);
    } catch (const std::invalid_argument& e) {
      throw ConfigError(std::string("--cloud: ") + e.what());
    }
  }
  return config;
}

std::optional<sky::SunOverride> SkyOptions::sunOverride() const {
  if (!sunAzimuth && !sunElevation) return std::nullopt;
  if (!sunAzimuth || !sunElevation)
    throw ConfigError("--sun-azimuth and --sun-elevation: give both or neither");
  return sky::SunOverride{*sunAzimuth, *sunElevation};
}

void parseSize(const std::string& text, int& width, int& height) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') ||
      w < sky::kMinChannelSide || h < sky::kMinChannelSide || w > sky::kMaxChannelSide || h > sky::kMaxChannelSide)
    throw ConfigError("--size: expected WIDTHxHEIGHT with each in " + std::to_string(sky::kMinChannelSide) + ".." +
                      std::to_string(sky::kMaxChannelSide) + ", got \"" + text + "\"");
  width = w;
  height = h;
}

}  // namespace skyig::services
