#include "node/config/node_config.h"

#include "physics/weather/cloud_layer.h"

#include "ephemeris/time.h"
#include "node/transport/udp_socket.h"
#include "physics/atmosphere/conditions.h"

#include <toml++/toml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace skyig::services {

namespace {

// Reads typed values out of a TOML table, remembering which keys were used so that a
// misspelt key is reported instead of silently ignored.
class TableReader {
 public:
  TableReader(const toml::table& table, std::string prefix, const std::string& source)
      : table_(table), prefix_(std::move(prefix)), source_(source) {}

  [[noreturn]] void fail(const toml::node* node, const std::string& key, const std::string& message) const {
    std::ostringstream out;
    const auto& region = node ? node->source() : table_.source();
    out << source_ << ":" << region.begin.line << ": " << prefix_ << key << ": " << message;
    throw ConfigError(out.str());
  }

  double number(const std::string& key, double value, double lo, double hi) {
    const toml::node* n = find(key);
    if (!n) return value;
    std::optional<double> v = n->value<double>();  // integers convert too
    if (!v || !std::isfinite(*v) || *v < lo || *v > hi)
      fail(n, key, "expected a number in [" + fmt(lo) + ", " + fmt(hi) + "], got " + show(*n));
    return *v;
  }

  int integer(const std::string& key, int value, int lo, int hi) {
    const toml::node* n = find(key);
    if (!n) return value;
    const std::optional<int64_t> v = n->is_integer() ? n->value<int64_t>() : std::nullopt;
    if (!v || *v < lo || *v > hi)
      fail(n, key, "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + show(*n));
    return static_cast<int>(*v);
  }

  bool boolean(const std::string& key, bool value) {
    const toml::node* n = find(key);
    if (!n) return value;
    if (!n->is_boolean()) fail(n, key, "expected true or false, got " + show(*n));
    return *n->value<bool>();
  }

  std::string string(const std::string& key, std::string value, const std::string& expected = "a string") {
    const toml::node* n = find(key);
    if (!n) return value;
    if (!n->is_string()) fail(n, key, "expected " + expected + ", got " + show(*n));
    return *n->value<std::string>();
  }

  const toml::node* find(const std::string& key) {
    used_.insert(key);
    return table_.get(key);
  }

  // Every key of the table must have been read.
  void rejectUnknownKeys() const {
    for (const auto& [key, node] : table_)
      if (!used_.count(std::string(key.str())))
        fail(&node, std::string(key.str()), "unknown key (misspelt? see config/skyig.toml for every key)");
  }

  const std::string& source() const { return source_; }
  const std::string& prefix() const { return prefix_; }

  // A value as the file wrote it (strings quoted), for error messages.
  static std::string show(const toml::node& n) {
    std::ostringstream o;
    n.visit([&o](const auto& x) { o << x; });
    return o.str();
  }

 private:
  static std::string fmt(double v) {
    std::ostringstream o;
    o << v;
    return o.str();
  }

  const toml::table& table_;
  std::string prefix_;
  const std::string& source_;
  std::set<std::string> used_;
};

const toml::table* subTable(TableReader& parent, const std::string& key) {
  const toml::node* n = parent.find(key);
  if (!n) return nullptr;
  if (!n->is_table()) parent.fail(n, key, "expected a table [" + key + "]");
  return n->as_table();
}

// [weather]: a ground fog (physics/weather/fog_layer.h) until the host sends its own (CIGI
// Weather Control layer 0): fog_visibility_km (0: none), fog_bottom_m, fog_top_m above the ground,
// fog_transition_m (the band over which its top, and a raised bottom, fade; 0: a hard edge);
// and precipitation or dust (physics/weather/precipitation.h, layers 4-9): precipitation ("none",
// "rain", "snow", "sleet", "hail", "sand", "dust"), precipitation_severity (0-5),
// precipitation_visibility_km (0: the severity's), precipitation_top_m, precipitation_coverage_pct.
// [[weather.cloud]]: up to three cloud layers (CIGI Weather Control layers 1-3) until the host
// sends its own.
skyig::sky::CloudLayer readCloud(TableReader& r) {
  skyig::sky::CloudLayer l;
  l.enabled = r.boolean("enabled", true);
  constexpr const char* kTypes =
      "\"altocumulus\", \"altostratus\", \"cirrocumulus\", \"cirrostratus\", \"cirrus\", \"cumulonimbus\", "
      "\"cumulus\", \"nimbostratus\", \"stratocumulus\" or \"stratus\"";
  const std::string type = r.string("type", "stratus", kTypes);
  const std::optional<skyig::sky::CloudType> parsed = skyig::weather::parseCloudType(type);
  if (!parsed) r.fail(r.find("type"), "type", "expected " + std::string(kTypes) + ", got \"" + type + "\"");
  l.type = *parsed;
  l.baseM = r.number("base_m", 300.0, 0.0, 20000.0);
  l.thicknessM = r.number("thickness_m", 400.0, 1.0, 20000.0);
  l.coveragePct = r.number("coverage_pct", 100.0, 0.0, 100.0);
  l.severity = r.integer("severity", 2, 0, 5);
  l.visibilityM = r.number("visibility_m", 0.0, 0.0, 100000.0);
  l.transitionM = r.number("transition_m", 0.0, 0.0, 20000.0);
  l.topTransitionM = r.number("top_transition_m", l.transitionM, 0.0, 20000.0);
  l.scud = r.boolean("scud", false);
  l.scudFrequencyPct = r.number("scud_frequency_pct", 0.0, 0.0, 100.0);
  l.windSpeedMps = r.number("wind_speed_mps", 0.0, 0.0, 150.0);
  l.windFromDeg = r.number("wind_from_deg", 0.0, -360.0, 360.0);
  r.rejectUnknownKeys();
  return l;
}

void readClouds(TableReader& r, skyig::sky::CloudLayers& clouds) {
  const toml::node* n = r.find("cloud");
  if (!n) return;
  const toml::array* list = n->as_array();
  if (!list || !list->is_array_of_tables() || list->size() > skyig::sky::kCloudLayers)
    r.fail(n, "cloud", "expected one to three [[weather.cloud]] tables (CIGI's cloud layers 1-3)");
  for (std::size_t i = 0; i < list->size(); ++i) {
    TableReader c(*list->get(i)->as_table(), r.prefix() + "cloud[" + std::to_string(i) + "].", r.source());
    clouds[i] = readCloud(c);
  }
}

void readWeather(TableReader& r, skyig::sky::FogSpec& fog, skyig::weather::PrecipitationSettings& rain,
                 skyig::sky::FogSpec& precipitation, skyig::sky::CloudLayers& clouds) {
  readClouds(r, clouds);
  fog.visibilityKm = r.number("fog_visibility_km", fog.visibilityKm, 0.0, atmosphere::kLargestVisibilityKm);
  fog.bottomM = r.number("fog_bottom_m", fog.bottomM, 0.0, 20000.0);
  fog.topM = r.number("fog_top_m", fog.topM, 0.0, 20000.0);
  fog.transitionM = r.number("fog_transition_m", fog.transitionM, 0.0, 20000.0);
  if (fog.visibilityKm > 0.0 && !(fog.topM > fog.bottomM))
    r.fail(r.find("fog_top_m"), "fog_top_m", "expected a top above fog_bottom_m (" + std::to_string(fog.bottomM) + " m)");
  constexpr const char* kKinds = "\"none\", \"rain\", \"snow\", \"sleet\", \"hail\", \"sand\" or \"dust\"";
  const std::string kind = r.string("precipitation", rain.kind ? std::string(skyig::weather::toString(*rain.kind)) : "none", kKinds);
  rain.kind = skyig::weather::parsePrecipitation(kind);
  if (!rain.kind && kind != "none")
    r.fail(r.find("precipitation"), "precipitation", "expected " + std::string(kKinds) + ", got \"" + kind + "\"");
  rain.severity = r.integer("precipitation_severity", rain.severity, 0, 5);
  rain.visibilityKm = r.number("precipitation_visibility_km", rain.visibilityKm, 0.0, atmosphere::kLargestVisibilityKm);
  rain.topM = r.number("precipitation_top_m", rain.topM, 1.0, 20000.0);
  rain.coveragePct = r.number("precipitation_coverage_pct", rain.coveragePct, 0.0, 100.0);
  precipitation = skyig::weather::precipitationLayer(rain);
  r.rejectUnknownKeys();
}

constexpr const char* kModels = "\"preetham\", \"cie\" or \"physical\"";

void readSky(TableReader& r, skyig::sky::SkyConditions& sky, AtmosphereSettings& atmosphere, std::string& starCatalogue) {
  const std::string model = r.string("model", std::string(skyig::sky::toString(sky.model)), kModels);
  if (!skyig::sky::parseSkyModel(model, sky.model)) r.fail(r.find("model"), "model", "expected " + std::string(kModels) + ", got \"" + model + "\"");
  sky.cieType = r.integer("cie_type", sky.cieType, 1, 15);
  sky.turbidity = r.number("turbidity", sky.turbidity, 1.7, 10.0);
  sky.groundAlbedo = r.number("ground_albedo", sky.groundAlbedo, 0.0, 1.0);
  constexpr const char* kTables = "\"small\", \"medium\" or \"default\"";
  atmosphere.tables = r.string("atmosphere_tables", atmosphere.tables, kTables);
  if (atmosphere.tables != "small" && atmosphere.tables != "medium" && atmosphere.tables != "default")
    r.fail(r.find("atmosphere_tables"), "atmosphere_tables", "expected " + std::string(kTables) + ", got \"" + atmosphere.tables + "\"");
  atmosphere.cacheDir = r.string("atmosphere_cache", atmosphere.cacheDir);
  atmosphere.cacheMaxBytes = static_cast<std::uint64_t>(
      r.integer("atmosphere_cache_max_mb", static_cast<int>(atmosphere.cacheMaxBytes >> 20), 0, 1 << 20)) << 20;
  atmosphere.buildIntervalS = r.number("atmosphere_build_interval", atmosphere.buildIntervalS, 0.0, 86400.0);
  if (const toml::node* n = r.find("atmosphere_visibility_steps")) {
    const toml::array* list = n->as_array();
    if (!list) r.fail(n, "atmosphere_visibility_steps", "expected a list of visibilities in km, e.g. [2, 5, 10, 20, 50]");
    atmosphere.visibilityStepsKm.clear();
    for (const toml::node& item : *list) {
      const std::optional<double> km = item.value<double>();
      if (!km || !(*km >= atmosphere::kSmallestVisibilityKm && *km <= atmosphere::kLargestVisibilityKm))
        r.fail(&item, "atmosphere_visibility_steps", "expected visibilities in km within [0.05, 1000]");
      atmosphere.visibilityStepsKm.push_back(*km);
    }
  }
  starCatalogue = r.string("star_catalogue", starCatalogue);
  r.rejectUnknownKeys();
}

// [atmosphere]: the medium of Bruneton & Neyret's model (physics/atmosphere/medium.h), in the
// units a meteorologist writes (km, m, per metre, Dobson units, degrees).
void readAtmosphere(TableReader& r, AtmosphereSettings& a) {
  atmosphere::Medium& m = a.medium;
  m.bottomRadiusM = 1e3 * r.number("ground_radius_km", m.bottomRadiusM / 1e3, 1000.0, 100000.0);
  m.topRadiusM = 1e3 * r.number("top_radius_km", m.topRadiusM / 1e3, 1000.0, 100000.0);
  m.rayleighScatteringAt1umPerM = r.number("rayleigh_scattering_1um", m.rayleighScatteringAt1umPerM, 0.0, 1e-3);
  m.rayleighScaleHeightM = r.number("rayleigh_scale_height", m.rayleighScaleHeightM, 100.0, 100000.0);
  // The aerosol type first (physics/atmosphere/aerosol_type.h): it sets the albedo, spectrum,
  // scale height, phase function and OPAC's standard amount, which the keys below may still change.
  const double aerosolHumidity = r.number("aerosol_humidity_pct", 100.0 * m.aerosolHumidity, 0.0, 99.0) / 100.0;
  if (const toml::node* n = r.find("aerosol_type")) {
    const std::string name = r.string("aerosol_type", "", "an aerosol type's name");
    const std::optional<atmosphere::AerosolType> type = atmosphere::parseAerosolType(name);
    if (!type) r.fail(n, "aerosol_type", "expected one of " + std::string(atmosphere::aerosolTypeNames()) + ", got \"" + name + "\"");
    m = atmosphere::withStandardAerosol(m, *type, aerosolHumidity);
  }
  m.mieExtinctionPerM = r.number("mie_extinction", m.mieExtinctionPerM, 0.0, 1e-2);
  if (r.find("visibility_km")) a.visibilityKm = r.number("visibility_km", 50.0, atmosphere::kSmallestVisibilityKm, atmosphere::kLargestVisibilityKm);
  m.mieSingleScatteringAlbedo = r.number("mie_single_scattering_albedo", m.mieSingleScatteringAlbedo, 0.0, 1.0);
  m.mieAngstromExponent = r.number("mie_angstrom_exponent", m.mieAngstromExponent, -1.0, 4.0);
  m.mieScaleHeightM = r.number("mie_scale_height", m.mieScaleHeightM, 10.0, 100000.0);
  m.miePhaseG = r.number("mie_phase_g", m.miePhaseG, -0.99, 0.99);
  m.ozoneColumnDu = r.number("ozone_column_du", m.ozoneColumnDu, 0.0, 1000.0);
  m.ozoneCentreAltitudeM = r.number("ozone_center_altitude", m.ozoneCentreAltitudeM, 0.0, 100000.0);
  m.ozoneHalfWidthM = r.number("ozone_half_width", m.ozoneHalfWidthM, 100.0, 100000.0);
  m.sunAngularRadiusRad =
      atmosphere::kDegree * r.number("sun_angular_radius_deg", m.sunAngularRadiusRad / atmosphere::kDegree, 0.01, 5.0);
  m.solarIrradianceScale = r.number("solar_irradiance_scale", m.solarIrradianceScale, 0.0, 100.0);
  a.scatteringOrders = r.integer("scattering_orders", a.scatteringOrders, 1, 10);
  r.rejectUnknownKeys();
  try {
    atmosphere::validate(m);  // what one key cannot tell: the top above the ground, the ozone layer inside
  } catch (const std::invalid_argument& e) {
    throw ConfigError(r.source() + ": atmosphere: " + e.what());
  }
}

void readObserver(TableReader& r, sky::ObserverState& o) {
  o.latitudeDeg = r.number("latitude", o.latitudeDeg, -90.0, 90.0);
  o.longitudeDeg = r.number("longitude", o.longitudeDeg, -180.0, 360.0);
  o.heightM = r.number("altitude", o.heightM, -400.0, 1e6);
  o.attitude.yawDeg = r.number("yaw", o.attitude.yawDeg, -360.0, 360.0);
  o.attitude.pitchDeg = r.number("pitch", o.attitude.pitchDeg, -90.0, 90.0);
  o.attitude.rollDeg = r.number("roll", o.attitude.rollDeg, -180.0, 180.0);
  if (const toml::node* n = r.find("utc")) {
    const std::optional<std::string> text = n->value<std::string>();
    const auto utc = text ? ephemeris::parseIso8601Utc(*text) : std::nullopt;
    if (!utc) r.fail(n, "utc", "expected a UTC time like \"2026-06-21T19:30:00Z\"");
    o.utc = *utc;
  }
  r.rejectUnknownKeys();
}

void readHost(TableReader& r, HostLink& h) {
  h.listen = r.string("listen", h.listen, "\"ADDRESS:PORT\"");
  try {
    (void)parseEndpoint(h.listen);  // a bad port or name is the file's error, whatever the command
  } catch (const NetworkError& e) {
    r.fail(r.find("listen"), "listen", e.what());
  }
  h.multicastGroup = r.string("multicast_group", h.multicastGroup, "an IPv4 multicast address");
  if (!h.multicastGroup.empty() && !isMulticastGroup(h.multicastGroup))
    r.fail(r.find("multicast_group"), "multicast_group",
           "expected an IPv4 multicast address (224.0.0.0 to 239.255.255.255), got \"" + h.multicastGroup + "\"");
  h.multicastInterface = r.string("multicast_interface", h.multicastInterface, "an IPv4 address");
  if (!h.multicastInterface.empty()) {
    if (!isIpv4Address(h.multicastInterface))
      r.fail(r.find("multicast_interface"), "multicast_interface",
             "expected the IPv4 address of an interface, e.g. \"10.20.0.11\" or \"127.0.0.1\", got \"" +
                 h.multicastInterface + "\"");
    if (h.multicastGroup.empty())
      r.fail(r.find("multicast_interface"), "multicast_interface", "names where multicast_group is joined: set multicast_group too");
  }
  h.replyPort = r.integer("reply_port", h.replyPort, 1, 65535);
  h.replyTo = r.string("reply_to", h.replyTo, "\"ADDRESS:PORT\" or \"\"");
  if (!h.replyTo.empty()) {
    try {
      parseEndpoint(h.replyTo);
    } catch (const NetworkError& e) {
      r.fail(r.find("reply_to"), "reply_to", e.what());
    }
  }
  if (const toml::node* n = r.find("allowed")) {
    const toml::array* list = n->as_array();
    if (!list) r.fail(n, "allowed", "expected a list of IPv4 addresses or CIDR blocks, e.g. [\"10.0.0.0/8\"]");
    if (list->empty())
      r.fail(n, "allowed", "an empty list would ignore every host; [\"0.0.0.0/0\"] accepts any address");
    h.session.allowed.clear();
    for (const toml::node& item : *list) {
      const std::optional<std::string> text = item.value<std::string>();
      if (!text) r.fail(&item, "allowed", "expected a list of strings (\"A.B.C.D\" or \"A.B.C.D/N\")");
      try {
        h.session.allowed.push_back(parseAddressRange(*text));
      } catch (const std::invalid_argument& e) {
        r.fail(&item, "allowed", e.what());
      }
    }
  }
  h.session.sessionGapS = r.number("session_gap", h.session.sessionGapS, 0.05, 3600.0);
  h.session.staleFrames =
      static_cast<std::uint32_t>(r.integer("stale_frames", static_cast<int>(h.session.staleFrames), 0, 100000));
  h.synchronous = r.boolean("synchronous", h.synchronous);
  h.syncTimeoutS = r.number("sync_timeout", h.syncTimeoutS, 0.001, 10.0);
  h.frameRateHz = r.number("frame_rate", h.frameRateHz, 1.0, 1000.0);
  h.canInterface = r.string("can_interface", h.canInterface);
  h.maxViews = r.integer("max_views", h.maxViews, 1, static_cast<int>(kViewTableCapacity));
  r.rejectUnknownKeys();
}

// [degrade]: when a node that cannot hold its frame rate lowers its channels' resolution.
void readDegrade(TableReader& r, DegradationSettings& d) {
  d.enabled = r.boolean("enabled", d.enabled);
  d.overFrames = r.integer("over_frames", d.overFrames, 1, 100000);
  d.releaseFrames = r.integer("release_frames", d.releaseFrames, 1, 100000);
  d.releaseHeadroom = r.number("release_headroom", d.releaseHeadroom, 0.05, 0.95);
  if (const toml::node* n = r.find("scales")) {
    const toml::array* list = n->as_array();
    if (!list || list->empty()) r.fail(n, "scales", "expected a list of scales below 1, descending, e.g. [0.75, 0.5]");
    d.scales.clear();
    for (const toml::node& item : *list) {
      const std::optional<double> s = item.value<double>();
      if (!s) r.fail(&item, "scales", "expected numbers, e.g. [0.75, 0.5]");
      d.scales.push_back(*s);
    }
    try {
      d.validate();
    } catch (const std::invalid_argument& e) {
      r.fail(n, "scales", e.what());
    }
  }
  r.rejectUnknownKeys();
}

void readCanIdentifiers(TableReader& r, protocol::canaerospace::IdentifierMap& m) {
  auto id = [&](const char* key, std::uint32_t& v) {
    v = static_cast<std::uint32_t>(r.integer(key, static_cast<int>(v), 0, 2047));  // 11-bit identifiers
  };
  id("body_pitch", m.bodyPitch);
  id("body_roll", m.bodyRoll);
  id("heading", m.heading);
  id("latitude", m.latitude);
  id("longitude", m.longitude);
  id("altitude", m.altitude);
  id("utc", m.utc);
  id("date", m.date);
  m.acceptLongLatLon1e7 = r.boolean("accept_long_lat_lon_1e7", m.acceptLongLatLon1e7);
  r.rejectUnknownKeys();
}

// [channel.projector]; relative files are found from the configuration's folder.
ProjectorSettings readProjector(TableReader& r, const std::string& configPath) {
  ProjectorSettings p;
  const auto file = [&](const std::string& key) {
    std::string path = r.string(key, "");
    if (r.find(key) && path.empty()) r.fail(r.find(key), key, "expected a file name, got \"\"");
    if (!path.empty() && std::filesystem::path(path).is_relative())
      path = (std::filesystem::path(configPath).parent_path() / path).lexically_normal().string();
    return path;
  };
  p.mpcdi = file("mpcdi");
  p.bourkeMesh = file("bourke_mesh");
  p.region = r.string("region", "");
  const std::string values = r.string("warp_values", "absolute", "\"absolute\" or \"offset\"");
  if (values != "absolute" && values != "offset")
    r.fail(r.find("warp_values"), "warp_values", "expected \"absolute\" or \"offset\", got \"" + values + "\"");
  p.warpOffsets = values == "offset";
  if (p.mpcdi.empty() == p.bourkeMesh.empty())
    r.fail(nullptr, "mpcdi", "expected either mpcdi = \"FILE\" (with region) or bourke_mesh = \"FILE\"");
  if (!p.mpcdi.empty() && p.region.empty())
    r.fail(r.find("region"), "region", "expected the MPCDI region this channel's projector shows");
  if (!p.bourkeMesh.empty() && r.find("region"))
    r.fail(r.find("region"), "region", "a Bourke mesh has no regions (the channel's frustum is its camera)");
  if (!p.bourkeMesh.empty() && r.find("warp_values"))
    r.fail(r.find("warp_values"), "warp_values", "applies to MPCDI warp files only");
  r.rejectUnknownKeys();
  return p;
}

// [channel.goggle]: a night-vision goggle in front of the channel (sky/channel.h GoggleParams).
// A channel with the table is a goggle the host can switch on (CIGI Sensor Control); `on`
// switches it on from the start. The class and the phosphor are the goggle's; the gain is
// "auto" (automatic brightness control) or the tube's gain as a fraction of its maximum.
void readGoggle(TableReader& r, sky::ChannelConfig& c) {
  sky::GoggleParams& g = c.goggle;
  const bool on = r.boolean("on", false);
  const std::string nvisClass = r.string("class", "A", "\"A\" or \"B\"");
  if (nvisClass == "A") g.nvisClass = sky::SpectralBand::NvisClassA;
  else if (nvisClass == "B") g.nvisClass = sky::SpectralBand::NvisClassB;
  else r.fail(r.find("class"), "class", "expected \"A\" or \"B\" (MIL-STD-3009 NVIS class), got \"" + nvisClass + "\"");
  const std::string phosphor = r.string("phosphor", "P43", "\"P43\" or \"P45\"");
  if (phosphor == "P43") g.phosphor = sky::Phosphor::P43;
  else if (phosphor == "P45") g.phosphor = sky::Phosphor::P45;
  else r.fail(r.find("phosphor"), "phosphor", "expected \"P43\" or \"P45\", got \"" + phosphor + "\"");
  if (const toml::node* n = r.find("fov_deg")) {
    const std::optional<double> v = n->value<double>();  // integers convert too
    if (!v || !std::isfinite(*v) || *v <= 0.0 || *v >= 180.0)
      r.fail(n, "fov_deg", "expected a circular field of view in degrees in (0, 180), got " + r.show(*n));
    g.fieldOfViewDeg = *v;
  }
  if (const toml::node* n = r.find("gain")) {
    const std::optional<double> v = n->is_string() ? std::nullopt : n->value<double>();
    if (n->is_string() && *n->value<std::string>() == "auto") {
      g.automaticGain = true;
    } else if (v && std::isfinite(*v) && *v > 0.0 && *v <= 1.0) {
      g.automaticGain = false;
      g.gain = *v;
    } else {
      r.fail(n, "gain", "expected \"auto\" or a fraction of the maximum gain in (0, 1], got " + r.show(*n));
    }
  }
  r.rejectUnknownKeys();
  if (on) c.band = g.nvisClass;
}

sky::ChannelConfig readChannel(TableReader& r, size_t index, std::string& node, ProjectorSettings& projector) {
  sky::ChannelConfig c;
  node = r.string("node", "");
  c.name = r.string("name", "channel" + std::to_string(index));
  if (c.name.empty() || c.name.find_first_of("/\\ \t") != std::string::npos)
    r.fail(r.find("name"), "name", "expected a non-empty name without spaces or slashes");
  c.offset.yawDeg = r.number("yaw", 0.0, -360.0, 360.0);
  c.offset.pitchDeg = r.number("pitch", 0.0, -90.0, 90.0);
  c.offset.rollDeg = r.number("roll", 0.0, -180.0, 180.0);
  c.frustum.leftDeg = r.number("left", c.frustum.leftDeg, 0.1, 89.0);
  c.frustum.rightDeg = r.number("right", c.frustum.rightDeg, 0.1, 89.0);
  c.frustum.downDeg = r.number("down", c.frustum.downDeg, 0.1, 89.0);
  c.frustum.upDeg = r.number("up", c.frustum.upDeg, 0.1, 89.0);
  c.monitor = r.string("monitor", c.monitor);
  c.width = r.integer("width", c.width, sky::kMinChannelSide, sky::kMaxChannelSide);
  c.height = r.integer("height", c.height, sky::kMinChannelSide, sky::kMaxChannelSide);
  if (const toml::table* t = subTable(r, "projector")) {
    TableReader p(*t, r.prefix() + "projector.", r.source());
    projector = readProjector(p, r.source());
    projector.sizeGiven = r.find("width") != nullptr || r.find("height") != nullptr;
    if (projector.sizeGiven && !(r.find("width") && r.find("height")))
      r.fail(r.find("width") ? r.find("width") : r.find("height"), r.find("width") ? "width" : "height",
             "a projector channel gives both width and height, or neither (the projector's resolution)");
  }
  if (const toml::table* t = subTable(r, "display")) {
    TableReader d(*t, r.prefix() + "display.", r.source());
    c.display.maxLuminance = d.number("max_luminance", c.display.maxLuminance, 1.0, 1e5);
    c.display.ambientLuminance = d.number("ambient_luminance", c.display.ambientLuminance, 0.0, 1e3);
    c.display.gamma = d.number("gamma", c.display.gamma, 1.0, 3.0);
    const std::string tone = d.string("tone_operator", "histogram", "\"histogram\" or \"tumblin_rushmeier\"");
    if (tone == "histogram") c.display.toneOperator = sky::ToneOperator::Histogram;
    else if (tone == "tumblin_rushmeier") c.display.toneOperator = sky::ToneOperator::TumblinRushmeier;
    else d.fail(d.find("tone_operator"), "tone_operator", "expected \"histogram\" or \"tumblin_rushmeier\", got \"" + tone + "\"");
    c.display.viewerAdaptationLuminance =
        d.number("adaptation_luminance", c.display.maxLuminance / 10.0, 0.01, 1e5);
    d.rejectUnknownKeys();
  }
  if (const toml::table* t = subTable(r, "goggle")) {
    TableReader g(*t, r.prefix() + "goggle.", r.source());
    readGoggle(g, c);
  }
  r.rejectUnknownKeys();
  return c;
}

}  // namespace

NodeConfig parseNodeConfig(const std::string& text, const std::string& sourceName) {
  toml::table root;
  try {
    root = toml::parse(text, sourceName);
  } catch (const toml::parse_error& e) {
    std::ostringstream out;
    out << sourceName << ":" << e.source().begin.line << ": " << e.description();
    throw ConfigError(out.str());
  }
  NodeConfig config;
  TableReader r(root, "", sourceName);
  if (const toml::table* t = subTable(r, "node")) {
    TableReader n(*t, "node.", sourceName);
    config.nodeName = n.string("name", config.nodeName);
    n.rejectUnknownKeys();
  }
  if (const toml::table* t = subTable(r, "sky")) {
    TableReader s(*t, "sky.", sourceName);
    readSky(s, config.sky, config.atmosphere, config.starCataloguePath);
  }
  if (const toml::table* t = subTable(r, "atmosphere")) {
    TableReader a(*t, "atmosphere.", sourceName);
    readAtmosphere(a, config.atmosphere);
  }
  if (const toml::table* t = subTable(r, "weather")) {
    TableReader w(*t, "weather.", sourceName);
    readWeather(w, config.sky.fog, config.precipitation, config.sky.precipitation, config.sky.clouds);
  }
  if (const toml::table* t = subTable(r, "observer")) {
    TableReader o(*t, "observer.", sourceName);
    readObserver(o, config.observer);
  }
  if (const toml::table* t = subTable(r, "eye")) {
    TableReader e(*t, "eye.", sourceName);
    const std::string mode = e.string("adaptation", "temporal", "\"temporal\" or \"instant\"");
    if (mode != "temporal" && mode != "instant")
      e.fail(e.find("adaptation"), "adaptation", "expected \"temporal\" or \"instant\", got \"" + mode + "\"");
    config.temporalAdaptation = mode == "temporal";
    e.rejectUnknownKeys();
  }
  if (const toml::table* t = subTable(r, "host")) {
    TableReader h(*t, "host.", sourceName);
    readHost(h, config.host);
  }
  if (const toml::table* t = subTable(r, "degrade")) {
    TableReader d(*t, "degrade.", sourceName);
    readDegrade(d, config.degrade);
  }
  if (const toml::table* t = subTable(r, "can_identifiers")) {
    TableReader c(*t, "can_identifiers.", sourceName);
    readCanIdentifiers(c, config.canIdentifiers);
  }
  if (const toml::node* n = r.find("channel")) {
    const toml::array* channels = n->as_array();
    if (!channels || channels->empty() || !channels->is_array_of_tables())
      r.fail(n, "channel", "expected one or more [[channel]] tables");
    config.channels.clear();
    config.channelNodes.clear();
    config.channelProjectors.clear();
    std::set<std::string> names;
    for (size_t i = 0; i < channels->size(); ++i) {
      const toml::table& t = *channels->get(i)->as_table();
      TableReader c(t, "channel[" + std::to_string(i) + "].", sourceName);
      std::string node;
      ProjectorSettings projector;
      config.channels.push_back(readChannel(c, i, node, projector));
      config.channelNodes.push_back(node);
      config.channelProjectors.push_back(projector);
      if (!names.insert(config.channels.back().name).second)
        c.fail(c.find("name"), "name", "duplicate channel name \"" + config.channels.back().name + "\"");
    }
  }
  r.rejectUnknownKeys();
  return config;
}

std::vector<sky::ChannelConfig> NodeConfig::channelsOf(const std::string& name) const {
  std::vector<sky::ChannelConfig> mine;
  for (size_t i = 0; i < channels.size(); ++i)
    if (channelNodes[i].empty() || channelNodes[i] == name) mine.push_back(channels[i]);
  return mine;
}

ProjectorSettings NodeConfig::projectorOf(const std::string& channel) const {
  for (size_t i = 0; i < channels.size() && i < channelProjectors.size(); ++i)
    if (channels[i].name == channel) return channelProjectors[i];
  return {};
}

NodeConfig loadNodeConfig(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path + ": cannot open the configuration file");
  // Read with a bound: /dev/zero, a FIFO that never ends or a huge file is refused, not read
  // into memory (a configuration is a few kilobytes).
  std::string text(kMaxConfigBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxConfigBytes)
    throw ConfigError(path + ": the configuration file is larger than " + std::to_string(kMaxConfigBytes >> 20) +
                      " MiB (is it a configuration?)");
  return parseNodeConfig(text, path);
}

}  // namespace skyig::services
