#include "commands/probe_command.h"

#include "ephemeris/ephemeris.h"
#include "commands/probe_json.h"
#include "physics/atmosphere/conditions.h"
#include "physics/atmosphere/probe.h"
#include "physics/weather/fog_layer.h"
#include "sky/client_light.h"
#include "sky/night_probe.h"
#include "sky/sky_state.h"
#include "node/config/node_tables.h"
#include "node/config/sky_data.h"
#include "physics/common/units.h"
#include "skyig/sky.h"

#include <cstdio>
#include <fstream>
#include <memory>
#include <numbers>

namespace skyig::services {

namespace {

struct ProbeCli {
  double altitudeM = 0.0;
  std::optional<double> sunZenith, sunAzimuth;
  std::optional<double> lat, lon;
  std::string utc;
  std::vector<std::string> views;
  std::string viewsFile;
  std::optional<double> visibilityKm, humidityPct, groundAlbedo;
  bool irradiance = false;
  bool light = false;
  std::optional<std::string> tables;  // default: the configuration's ("medium" without one)
  std::optional<std::string> cacheDir;
  std::optional<int> orders;
  std::string configPath;
  std::string starCatalogue;  // "" = the bundled BSC5
};

atmosphere::ProbeView parseView(const std::string& text, const std::string& where) {
  double z = 0.0, a = 0.0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf%c", &z, &a, &extra) != 2 || !(z >= 0.0 && z <= 180.0) || !std::isfinite(a))
    throw ConfigError(where + ": expected ZENITH,AZIMUTH in degrees (zenith 0..180), got \"" + text + "\"");
  return {z, a};
}

// The weather's layers over the tables, as the node draws them: the haze below the tables'
// visibility (nodeHaze), the configuration's ground fog and precipitation ([weather]).
void addWeatherLayers(sky::SkyConditions& sky, const NodeConfig& node) {
  sky.haze = nodeHaze(node, node.atmosphere.visibilityKm.value_or(0.0));
  sky.fog = node.sky.fog;
  sky.precipitation = node.sky.precipitation;
}

// Each view's sky or ground, lit by the sun and the moon, through the weather's layers: what the
// frame shows there (sky/client_light.h, clientSkyRadiance, the composition of the sky pass),
// beside the tables' figures, which leave the layers out.
void addThroughLayers(nlohmann::json& out, const sky::SkyState& state, const atmosphere::AtmosphereModel& model,
                      const std::vector<atmosphere::ProbeView>& views) {
  if (!state.fog.any()) return;
  for (std::size_t i = 0; i < views.size(); ++i) {
    const double z = views[i].zenithDeg * kDeg, a = views[i].azimuthDeg * kDeg;
    const glm::dvec3 view(std::sin(z) * std::sin(a), std::sin(z) * std::cos(a), std::cos(z));
    const glm::dvec3 rgb = sky::clientSkyRadiance(state, &model, view);
    out["views"][i]["through_layers"] = {{"rgb_cd_m2", {rgb.r, rgb.g, rgb.b}},
                                         {"luminance_cd_m2", 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b}};
  }
}

// `--light`: the light a host embedding skyig gets, through the public API (skyig::Sky): the
// command is the library's first client, so what it prints is what a host receives.
int runLight(const ProbeCli& cli) {
  if (!cli.lat || !cli.lon || cli.utc.empty()) throw ConfigError("--light: give --lat, --lon and --utc");
  const auto utc = ephemeris::parseIso8601Utc(cli.utc);
  if (!utc) throw ConfigError("--utc: expected a UTC time like 2026-06-21T19:30:00Z, got \"" + cli.utc + "\"");
  skyig::Settings settings;
  settings.configFile = cli.configPath;
  settings.tables = cli.tables.value_or("");
  settings.visibilityKm = cli.visibilityKm.value_or(0.0);
  settings.temporalAdaptation = false;  // a still: the eye adapted to it
  skyig::Observer observer;
  observer.latitudeDeg = *cli.lat;
  observer.longitudeDeg = *cli.lon;
  observer.heightM = cli.altitudeM;
  observer.utc = {utc->year, utc->month, utc->day, utc->secondsOfDay};
  try {
    skyig::Sky sky(settings);
    sky.update(observer, 0.0);
    nlohmann::json out = {{"utc", cli.utc}, {"latitude_deg", *cli.lat}, {"longitude_deg", *cli.lon},
                          {"altitude_m", cli.altitudeM}, {"light", libraryLightJson(sky.light())}};
    std::printf("%s\n", out.dump(2).c_str());
  } catch (const skyig::Error& e) {
    throw ConfigError(e.what());
  }
  return 0;
}

int run(const ProbeCli& cli) {
  if (cli.light) return runLight(cli);
  atmosphere::ProbeRequest request;
  request.altitudeM = cli.altitudeM;
  request.irradiance = cli.irradiance;
  if (cli.sunZenith || cli.sunAzimuth) {
    if (!cli.sunZenith || !cli.sunAzimuth) throw ConfigError("--sun-zenith and --sun-azimuth: give both, or a place and time");
    request.sunZenithDeg = *cli.sunZenith;
    request.sunAzimuthDeg = *cli.sunAzimuth;
  }
  std::optional<sky::ObserverState> place;  // a time and place: the night components too
  if (!cli.sunZenith && !cli.sunAzimuth) {
    if (!cli.lat || !cli.lon || cli.utc.empty())
      throw ConfigError("the sun: give --sun-zenith and --sun-azimuth, or --lat, --lon and --utc");
    const auto utc = ephemeris::parseIso8601Utc(cli.utc);
    if (!utc) throw ConfigError("--utc: expected a UTC time like 2026-06-21T19:30:00Z, got \"" + cli.utc + "\"");
    place.emplace();
    place->latitudeDeg = *cli.lat;
    place->longitudeDeg = *cli.lon;
    place->heightM = cli.altitudeM;
    place->utc = *utc;
  }
  for (const auto& v : cli.views) request.views.push_back(parseView(v, "--view"));
  if (!cli.viewsFile.empty()) {
    std::ifstream in(cli.viewsFile);
    if (!in) throw ConfigError(cli.viewsFile + ": cannot open the views file");
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      if (line.empty() || line[0] == '#') continue;
      request.views.push_back(parseView(line, cli.viewsFile + ":" + std::to_string(n)));
    }
  }
  if (request.views.empty()) request.views.push_back({0.0, 0.0});  // the zenith

  // The node's atmosphere as `render` and `serve` load it (loadNodeAtmosphere: [atmosphere],
  // sky.atmosphere_tables, sky.ground_albedo, [atmosphere] visibility_km; the embedded defaults
  // without a configuration), so the probe reads the same tables from the same cache file; the
  // flags override it.
  NodeConfig node = cli.configPath.empty() ? NodeConfig{} : loadNodeConfig(cli.configPath);
  if (cli.tables) node.atmosphere.tables = *cli.tables;
  if (cli.cacheDir) node.atmosphere.cacheDir = *cli.cacheDir;
  if (cli.orders) node.atmosphere.scatteringOrders = *cli.orders;
  if (cli.visibilityKm) node.atmosphere.visibilityKm = *cli.visibilityKm;
  if (cli.groundAlbedo) node.sky.groundAlbedo = *cli.groundAlbedo;
  atmosphere::Conditions conditions;
  if (cli.humidityPct) conditions.relativeHumidity = *cli.humidityPct / 100.0;
  const auto model = loadNodeAtmosphere(node, conditions);
  sky::SkyConditions sky;
  sky.model = sky::SkyModel::Physical;
  sky.atmosphere = model;
  addWeatherLayers(sky, node);
  // Below the tables' lowest visibility the node draws the rest as a haze layer: the tables'
  // figures leave it out, each view's through_layers has it.
  if (const double km = node.atmosphere.visibilityKm.value_or(0.0); km > 0.0 && km < weather::kTablesVisibilityKm)
    std::fprintf(stderr,
                 "probe: visibility %.3g km is below the tables' %.3g km: the sky, ground and irradiance figures are "
                 "the %.3g km tables', each view's through_layers adds the haze layer the node draws over them "
                 "(docs/atmosphere.md, \"Low visibility\")\n",
                 km, weather::kTablesVisibilityKm, weather::kTablesVisibilityKm);
  if (!place) {
    nlohmann::json out = probeJson(atmosphere::probe(*model, request));
    sky::ObserverState observer;
    observer.heightM = request.altitudeM;
    const sky::SkyState state =
        sky::buildSkyState(observer, sky, sky::SunOverride{request.sunAzimuthDeg, 90.0 - request.sunZenithDeg});
    addThroughLayers(out, state, *model, request.views);
    std::printf("%s\n", out.dump(2).c_str());
    return 0;
  }
  sky.starCatalogue = loadConfiguredStarCatalogue(cli.starCatalogue, place->utc);
  const sky::SkyState state = sky::buildSkyState(*place, sky);
  nlohmann::json out = nightProbeJson(sky::nightProbe(*model, state, request));
  addThroughLayers(out, state, *model, request.views);
  std::printf("%s\n", out.dump(2).c_str());
  return 0;
}

}  // namespace

void registerProbeCommand(CLI::App& app, int& exitCode) {
  auto cli = std::make_shared<ProbeCli>();
  CLI::App* c = app.add_subcommand("probe", "Sky, sun and ground radiance of the physical atmosphere in view directions, as JSON; with --lat --lon --utc also each night light source and the total");
  c->add_option("--alt", cli->altitudeM, "Observer altitude above the ground, m (0)")->check(CLI::Range(0.0, 1e6));
  c->add_option("--sun-zenith", cli->sunZenith, "Sun zenith angle, degrees")->check(CLI::Range(0.0, 180.0));
  c->add_option("--sun-azimuth", cli->sunAzimuth, "Sun azimuth, degrees from north through east")->check(CLI::Range(-360.0, 360.0));
  c->add_option("--lat", cli->lat, "Or the sun of a place and time: latitude, degrees")->check(CLI::Range(-90.0, 90.0));
  c->add_option("--lon", cli->lon, "Longitude, degrees east")->check(CLI::Range(-180.0, 360.0));
  c->add_option("--utc", cli->utc, "UTC date and time");
  c->add_option("--view", cli->views, "A view direction ZENITH,AZIMUTH in degrees (repeatable; default: the zenith)");
  c->add_option("--views", cli->viewsFile, "A file of view directions, one ZENITH,AZIMUTH a line")->check(CLI::ExistingFile);
  c->add_option("--visibility", cli->visibilityKm, "Visibility, km (Koschmieder; default: the configuration's, else the clear medium's)")->check(CLI::Range(atmosphere::kSmallestVisibilityKm, atmosphere::kLargestVisibilityKm));
  c->add_option("--humidity", cli->humidityPct, "Relative humidity, percent")->check(CLI::Range(0.0, 99.0));
  c->add_option("--ground-albedo", cli->groundAlbedo, "Ground albedo, 0..1 (default: the configuration's sky.ground_albedo, 0.2 without one)")->check(CLI::Range(0.0, 1.0));
  c->add_flag("--irradiance", cli->irradiance, "Add the direct-sun and sky illuminance on a horizontal surface");
  c->add_flag("--light", cli->light, "Instead: the light a host embedding skyig gets (skyig::Sky::light: sun, moon, sky ambient and spherical harmonics, adaptation) for --lat --lon --utc [--alt --config --tables --visibility]");
  c->add_option("--tables", cli->tables, "Table size: medium (the node's default), small (seconds; coarse at sunset) or default (Bruneton's)")
      ->check(CLI::IsMember({"small", "medium", "default"}));
  c->add_option("--orders", cli->orders, "Scattering orders (4)")->check(CLI::Range(1, 10));
  c->add_option("--config", cli->configPath, "Node configuration (TOML): its [atmosphere] medium, table size and ground albedo")
      ->check(CLI::ExistingFile);
  c->add_option("--star-catalogue", cli->starCatalogue, "Star catalogue CSV for the stars_planets key (default: the bundled BSC5; none: planets only)");
  c->add_option("--cache", cli->cacheDir, "Table cache directory (default: $CACHE_DIRECTORY, else $XDG_CACHE_HOME/skyig or ~/.cache/skyig)");
  c->callback([cli, &exitCode] { exitCode = run(*cli); });
}

}  // namespace skyig::services
