// Configuration files: the documented defaults, the example dome, and clear errors that name
// the file, the line, the key and what was expected.
#include "node/config/node_config.h"

#include <gtest/gtest.h>

#include <string>

using namespace skyig::services;

namespace {
std::string source(const std::string& rel) { return std::string(SKYIG_SOURCE_DIR) + "/" + rel; }

std::string errorOf(const std::string& text) {
  try {
    parseNodeConfig(text, "bad.toml");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}
}  // namespace

// config/skyig.toml documents every key with its default: parsing it must give the built-in
// defaults, so the documentation cannot drift from the code.
TEST(NodeConfig, DocumentedDefaultsEqualBuiltInDefaults) {
  const NodeConfig file = loadNodeConfig(source("config/skyig.toml"));
  const NodeConfig builtIn = parseNodeConfig("", "empty");
  EXPECT_EQ(file.nodeName, builtIn.nodeName);
  EXPECT_EQ(file.sky.model, builtIn.sky.model);
  EXPECT_EQ(file.sky.cieType, builtIn.sky.cieType);
  EXPECT_EQ(file.sky.turbidity, builtIn.sky.turbidity);
  EXPECT_EQ(file.sky.groundAlbedo, builtIn.sky.groundAlbedo);
  EXPECT_EQ(file.atmosphere.tables, builtIn.atmosphere.tables);
  EXPECT_EQ(file.atmosphere.cacheDir, builtIn.atmosphere.cacheDir);
  EXPECT_EQ(file.starCataloguePath, builtIn.starCataloguePath);
  EXPECT_TRUE(file.atmosphere.medium == builtIn.atmosphere.medium);
  EXPECT_EQ(file.atmosphere.scatteringOrders, builtIn.atmosphere.scatteringOrders);
  EXPECT_EQ(file.observer.latitudeDeg, builtIn.observer.latitudeDeg);
  EXPECT_EQ(file.observer.longitudeDeg, builtIn.observer.longitudeDeg);
  EXPECT_EQ(file.observer.heightM, builtIn.observer.heightM);
  EXPECT_EQ(file.observer.attitude.yawDeg, builtIn.observer.attitude.yawDeg);
  EXPECT_EQ(file.observer.attitude.pitchDeg, builtIn.observer.attitude.pitchDeg);
  EXPECT_EQ(file.observer.utc.secondsOfDay, builtIn.observer.utc.secondsOfDay);
  EXPECT_EQ(file.observer.utc.day, builtIn.observer.utc.day);
  EXPECT_EQ(file.host.listen, builtIn.host.listen);
  EXPECT_EQ(file.host.multicastGroup, builtIn.host.multicastGroup);
  EXPECT_EQ(file.host.multicastInterface, builtIn.host.multicastInterface);
  EXPECT_EQ(file.host.replyPort, builtIn.host.replyPort);
  EXPECT_EQ(file.host.synchronous, builtIn.host.synchronous);
  EXPECT_EQ(file.host.syncTimeoutS, builtIn.host.syncTimeoutS);
  EXPECT_EQ(file.host.frameRateHz, builtIn.host.frameRateHz);
  EXPECT_EQ(file.host.canInterface, builtIn.host.canInterface);
  EXPECT_EQ(file.host.replyTo, builtIn.host.replyTo);
  ASSERT_EQ(file.host.session.allowed.size(), builtIn.host.session.allowed.size());
  for (std::size_t i = 0; i < file.host.session.allowed.size(); ++i)
    EXPECT_EQ(file.host.session.allowed[i].toString(), builtIn.host.session.allowed[i].toString());
  EXPECT_EQ(file.host.session.sessionGapS, builtIn.host.session.sessionGapS);
  EXPECT_EQ(file.host.session.staleFrames, builtIn.host.session.staleFrames);
  EXPECT_EQ(file.degrade.enabled, builtIn.degrade.enabled);
  EXPECT_EQ(file.degrade.overFrames, builtIn.degrade.overFrames);
  EXPECT_EQ(file.degrade.scales, builtIn.degrade.scales);
  EXPECT_EQ(file.degrade.releaseHeadroom, builtIn.degrade.releaseHeadroom);
  EXPECT_EQ(file.degrade.releaseFrames, builtIn.degrade.releaseFrames);
  EXPECT_EQ(file.canIdentifiers.bodyPitch, builtIn.canIdentifiers.bodyPitch);
  EXPECT_EQ(file.canIdentifiers.heading, builtIn.canIdentifiers.heading);
  EXPECT_EQ(file.canIdentifiers.latitude, builtIn.canIdentifiers.latitude);
  EXPECT_EQ(file.canIdentifiers.date, builtIn.canIdentifiers.date);
  EXPECT_EQ(file.canIdentifiers.acceptLongLatLon1e7, builtIn.canIdentifiers.acceptLongLatLon1e7);
  ASSERT_EQ(file.channels.size(), 1u);
  EXPECT_EQ(file.channelNodes, builtIn.channelNodes);
  const auto& a = file.channels[0];
  const auto& b = builtIn.channels[0];
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.frustum.leftDeg, b.frustum.leftDeg);
  EXPECT_EQ(a.frustum.upDeg, b.frustum.upDeg);
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.monitor, b.monitor);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.display.maxLuminance, b.display.maxLuminance);
  EXPECT_EQ(a.display.ambientLuminance, b.display.ambientLuminance);
  EXPECT_EQ(a.display.gamma, b.display.gamma);
  EXPECT_EQ(a.display.viewerAdaptationLuminance, b.display.viewerAdaptationLuminance);
  EXPECT_EQ(a.band, b.band);
  EXPECT_EQ(a.goggle, b.goggle);
}

TEST(NodeConfig, DomeHasFiveChannelsWithChinWindows) {
  const NodeConfig c = loadNodeConfig(source("config/dome5.toml"));
  ASSERT_EQ(c.channels.size(), 5u);
  EXPECT_EQ(c.channels[3].name, "chin-left");
  EXPECT_EQ(c.channels[3].offset.pitchDeg, -45.0);
  EXPECT_EQ(c.channels[3].frustum.leftDeg, 25.0);
  EXPECT_EQ(c.channels[3].frustum.rightDeg, 15.0);
  EXPECT_EQ(c.channels[0].display.viewerAdaptationLuminance, 5.0);  // defaults to max_luminance / 10
}

TEST(NodeConfig, OutOfRangeValueNamesFileLineKeyAndRange) {
  EXPECT_EQ(errorOf("[[channel]]\nname = \"a\"\nwidth = -5\n"),
            "bad.toml:3: channel[0].width: expected an integer in [16, 8192], got -5");
  EXPECT_EQ(errorOf("[sky]\nturbidity = 40\n"), "bad.toml:2: sky.turbidity: expected a number in [1.7, 10], got 40");
}

TEST(NodeConfig, WrongTypeAndUnknownKeys) {
  EXPECT_EQ(errorOf("[sky]\nmodel = 3\n"), "bad.toml:2: sky.model: expected \"preetham\", \"cie\" or \"physical\", got 3");
  EXPECT_EQ(errorOf("[sky]\nmodel = \"nishita\"\n"),
            "bad.toml:2: sky.model: expected \"preetham\", \"cie\" or \"physical\", got \"nishita\"");
  EXPECT_NE(errorOf("[sky]\nturbidty = 3\n").find("bad.toml:2: sky.turbidty: unknown key"), std::string::npos);
  EXPECT_NE(errorOf("[[channel]]\n[channel.display]\ngama = 2\n").find("bad.toml:3: channel[0].display.gama: unknown key"),
            std::string::npos);
  EXPECT_EQ(errorOf("[observer]\nutc = \"tomorrow\"\n"),
            "bad.toml:2: observer.utc: expected a UTC time like \"2026-06-21T19:30:00Z\"");
}

// [weather]: a ground fog and a precipitation layer from the ground up; a kind it does not know
// is named with the line.
TEST(NodeConfig, WeatherFogAndPrecipitation) {
  const NodeConfig c = parseNodeConfig(
      "[weather]\nfog_visibility_km = 0.4\nfog_top_m = 200\nprecipitation = \"snow\"\nprecipitation_severity = 4\n"
      "precipitation_top_m = 900\nprecipitation_coverage_pct = 50\n",
      "w.toml");
  EXPECT_EQ(c.sky.fog, (skyig::sky::FogSpec{0.0, 200.0, 0.4}));
  EXPECT_EQ(c.precipitation.kind, skyig::weather::Precipitation::snow);
  EXPECT_EQ(c.sky.precipitation.topM, 900.0);
  EXPECT_EQ(c.sky.precipitation.visibilityKm, 2.0 * skyig::weather::visibilityForSeverityKm(skyig::weather::Precipitation::snow, 4));
  EXPECT_EQ(parseNodeConfig("[weather]\nprecipitation = \"none\"\n", "w.toml").sky.precipitation.visibilityKm, 0.0);
  EXPECT_EQ(parseNodeConfig("[weather]\nfog_visibility_km = 0.4\nfog_top_m = 200\nfog_transition_m = 50\n", "w.toml")
                .sky.fog.transitionM,
            50.0);
  EXPECT_NE(errorOf("[weather]\nfog_transition_m = -1\n").find("bad.toml:2: weather.fog_transition_m"), std::string::npos);
  EXPECT_EQ(errorOf("[weather]\nprecipitation = \"drizzle\"\n"),
            "bad.toml:2: weather.precipitation: expected \"none\", \"rain\", \"snow\", \"sleet\", \"hail\", \"sand\" or "
            "\"dust\", got \"drizzle\"");
  EXPECT_EQ(errorOf("[weather]\nprecipitation_severity = 9\n"),
            "bad.toml:2: weather.precipitation_severity: expected an integer in [0, 5], got 9");
}

TEST(NodeConfig, SyntaxErrorsAndDuplicates) {
  EXPECT_NE(errorOf("[sky\nmodel = 1\n").find("bad.toml:1:"), std::string::npos);
  EXPECT_EQ(errorOf("[[channel]]\nname = \"a\"\n[[channel]]\nname = \"a\"\n"),
            "bad.toml:4: channel[1].name: duplicate channel name \"a\"");
  EXPECT_EQ(errorOf("[sky]\nturbidity = nan\n"), "bad.toml:2: sky.turbidity: expected a number in [1.7, 10], got nan");
}

// A shared dome configuration: each node renders the channels assigned to it.
TEST(NodeConfig, NodesSelectTheirChannels) {
  const NodeConfig c = parseNodeConfig(
      "[[channel]]\nname = \"a\"\nnode = \"ig1\"\n[[channel]]\nname = \"b\"\nnode = \"ig2\"\n"
      "[[channel]]\nname = \"c\"\n",
      "dome.toml");
  const auto ig1 = c.channelsOf("ig1");
  ASSERT_EQ(ig1.size(), 2u);
  EXPECT_EQ(ig1[0].name, "a");
  EXPECT_EQ(ig1[1].name, "c");  // unassigned: every node
  EXPECT_EQ(c.channelsOf("ig2")[0].name, "b");
}

TEST(NodeConfig, HostSectionErrors) {
  EXPECT_EQ(errorOf("[host]\nreply_port = 70000\n"), "bad.toml:2: host.reply_port: expected an integer in [1, 65535], got 70000");
  EXPECT_EQ(errorOf("[host]\nsynchronous = \"yes\"\n"), "bad.toml:2: host.synchronous: expected true or false, got 'yes'");
  EXPECT_EQ(errorOf("[host]\nmax_views = 65\n"), "bad.toml:2: host.max_views: expected an integer in [1, 64], got 65");
  EXPECT_EQ(parseNodeConfig("[host]\nmax_views = 4\n", "ok.toml").host.maxViews, 4);
  EXPECT_EQ(errorOf("[can_identifiers]\nheading = 4000\n"),
            "bad.toml:2: can_identifiers.heading: expected an integer in [0, 2047], got 4000");
  EXPECT_EQ(
      errorOf("[host]\nallowed = [\"10.0.0.0/8\",\n  \"10.1.2.3/8\"]\n"),
      "bad.toml:3: host.allowed: \"10.1.2.3/8\": address bits set beyond the /8 prefix (did you mean 10.0.0.0/8?)");
  EXPECT_EQ(errorOf("[host]\nallowed = []\n"),
            "bad.toml:2: host.allowed: an empty list would ignore every host; [\"0.0.0.0/0\"] accepts any address");
  // reply_to takes an address or a host name (as host.listen does); .invalid never resolves (RFC 6761).
  EXPECT_EQ(errorOf("[host]\nreply_to = \"host\"\n"),
            "bad.toml:2: host.reply_to: \"host\" is not ADDRESS:PORT (an IPv4 address or a host name)");
  EXPECT_EQ(errorOf("[host]\nreply_to = \"no-such-host.invalid:8005\"\n").find(
                "bad.toml:2: host.reply_to: \"no-such-host.invalid:8005\": cannot resolve \"no-such-host.invalid\""),
            0u);
  EXPECT_EQ(errorOf("[host]\nsession_gap = 0\n"),
            "bad.toml:2: host.session_gap: expected a number in [0.05, 3600], got 0");
  const NodeConfig c = parseNodeConfig(
      "[host]\nallowed = [\"192.168.7.20\", \"10.9.0.0/16\"]\nreply_to = \"192.168.7.20:8005\"\n", "ok");
  ASSERT_EQ(c.host.session.allowed.size(), 2u);
  EXPECT_EQ(c.host.session.allowed[1].toString(), "10.9.0.0/16");
  EXPECT_EQ(c.host.replyTo, "192.168.7.20:8005");
}

TEST(NodeConfig, CloudLayersAreReadAndTheirBadValuesNamed) {
  const NodeConfig c = parseNodeConfig(
      "[weather]\n[[weather.cloud]]\ntype = \"stratus\"\nbase_m = 300\nthickness_m = 400\n"
      "[[weather.cloud]]\ntype = \"cirrus\"\nbase_m = 9000\nthickness_m = 500\ncoverage_pct = 40\n", "ok.toml");
  EXPECT_TRUE(c.sky.clouds[0].enabled);
  EXPECT_EQ(c.sky.clouds[0].type, skyig::sky::CloudType::Stratus);
  EXPECT_EQ(c.sky.clouds[0].coveragePct, 100.0);
  EXPECT_EQ(c.sky.clouds[1].type, skyig::sky::CloudType::Cirrus);
  EXPECT_EQ(c.sky.clouds[1].baseM, 9000.0);
  EXPECT_FALSE(c.sky.clouds[2].enabled);
  EXPECT_FALSE(parseNodeConfig("", "empty").sky.clouds[0].enabled) << "no cloud by default";
  EXPECT_EQ(errorOf("[weather]\n[[weather.cloud]]\ntype = \"fog\"\n").find(
                "bad.toml:3: weather.cloud[0].type: expected \"altocumulus\""), 0u);
  EXPECT_EQ(errorOf("[weather]\n[[weather.cloud]]\ncoverage_pct = 120\n"),
            "bad.toml:3: weather.cloud[0].coverage_pct: expected a number in [0, 100], got 120");
  EXPECT_EQ(errorOf("[weather]\n[[weather.cloud]]\n[[weather.cloud]]\n[[weather.cloud]]\n[[weather.cloud]]\n").find(
                "bad.toml:"), 0u);
}

TEST(NodeConfig, DegradeSectionIsReadAndItsBadValuesNamed) {
  const NodeConfig c =
      parseNodeConfig("[degrade]\nenabled = true\nover_frames = 10\nscales = [0.8, 0.6, 0.4]\n", "ok.toml");
  EXPECT_TRUE(c.degrade.enabled);
  EXPECT_EQ(c.degrade.overFrames, 10);
  EXPECT_EQ(c.degrade.scales, (std::vector<double>{0.8, 0.6, 0.4}));
  EXPECT_EQ(errorOf("[degrade]\nscales = [0.5, 0.75]\n"),
            "bad.toml:2: degrade.scales: scales: 0.75 is not from 0.25 up to and below the level above's 0.5");
  EXPECT_EQ(errorOf("[degrade]\nscales = []\n"),
            "bad.toml:2: degrade.scales: expected a list of scales below 1, descending, e.g. [0.75, 0.5]");
  EXPECT_EQ(errorOf("[degrade]\nrelease_headroom = 1.5\n"),
            "bad.toml:2: degrade.release_headroom: expected a number in [0.05, 0.95], got 1.5");
  EXPECT_EQ(errorOf("[degrade]\nlevels = 3\n").find("bad.toml:2: degrade.levels"), 0u);
}

// [atmosphere] aerosol_type: an OPAC type brings its particles and OPAC's standard amount, which
// the mie_ keys may still change; an unknown name is refused with the file, line and the names.
TEST(NodeConfig, AerosolTypeSetsTheParticles) {
  const NodeConfig c = parseNodeConfig("[atmosphere]\naerosol_type = \"maritime_clean\"\naerosol_humidity_pct = 80\n", "t.toml");
  const skyig::atmosphere::Medium& m = c.atmosphere.medium;
  EXPECT_EQ(m.aerosolType, skyig::atmosphere::AerosolType::maritimeClean);
  EXPECT_EQ(m.aerosolHumidity, 0.8);
  const skyig::atmosphere::AerosolOptics o = skyig::atmosphere::aerosolOptics(skyig::atmosphere::AerosolType::maritimeClean, 0.8);
  EXPECT_DOUBLE_EQ(m.mieSingleScatteringAlbedo, o.singleScatteringAlbedo);
  EXPECT_DOUBLE_EQ(m.mieExtinctionPerM, 1e-3 * o.extinctionAt550PerKm);
  EXPECT_DOUBLE_EQ(m.mieScaleHeightM, o.scaleHeightM);
  EXPECT_EQ(parseNodeConfig("[atmosphere]\naerosol_type = \"urban\"\nmie_extinction = 1e-4\n", "t.toml")
                .atmosphere.medium.mieExtinctionPerM, 1e-4);
  EXPECT_EQ(parseNodeConfig("", "empty").atmosphere.medium.aerosolType, skyig::atmosphere::AerosolType::bruneton2017);
  const std::string err = errorOf("[atmosphere]\naerosol_type = \"smog\"\n");
  EXPECT_NE(err.find("bad.toml:2: atmosphere.aerosol_type: expected one of bruneton2017, continental_clean"), std::string::npos) << err;
  EXPECT_NE(err.find("got \"smog\""), std::string::npos) << err;
  EXPECT_NE(errorOf("[atmosphere]\naerosol_humidity_pct = 100\n").find("atmosphere.aerosol_humidity_pct"), std::string::npos);
}

TEST(NodeConfig, MissingFile) {
  EXPECT_THROW(loadNodeConfig("/nonexistent/skyig.toml"), ConfigError);
}

// The physical sky's table sizes: the three names, medium by default; anything else is named.
TEST(NodeConfig, AtmosphereTablesAndStarCatalogue) {
  EXPECT_EQ(parseNodeConfig("", "empty").atmosphere.tables, "medium");
  for (const char* size : {"small", "medium", "default"})
    EXPECT_EQ(parseNodeConfig(std::string("[sky]\natmosphere_tables = \"") + size + "\"\n", "t.toml").atmosphere.tables, size);
  EXPECT_NE(errorOf("[sky]\natmosphere_tables = \"huge\"\n").find("bad.toml:2: sky.atmosphere_tables: expected \"small\", \"medium\" or \"default\", got \"huge\""),
            std::string::npos)
      << errorOf("[sky]\natmosphere_tables = \"huge\"\n");
  EXPECT_EQ(parseNodeConfig("[sky]\nstar_catalogue = \"none\"\n", "t.toml").starCataloguePath, "none");
  // The cache's bound and the precompute rate: 512 MB and one a minute unless told otherwise.
  EXPECT_EQ(parseNodeConfig("", "empty").atmosphere.cacheMaxBytes, 512ull << 20);
  EXPECT_EQ(parseNodeConfig("", "empty").atmosphere.buildIntervalS, 60.0);
  const NodeConfig bounded = parseNodeConfig("[sky]\natmosphere_cache_max_mb = 64\natmosphere_build_interval = 0\n", "t.toml");
  EXPECT_EQ(bounded.atmosphere.cacheMaxBytes, 64ull << 20);
  EXPECT_EQ(bounded.atmosphere.buildIntervalS, 0.0);
  EXPECT_EQ(errorOf("[sky]\natmosphere_cache_max_mb = -1\n"),
            "bad.toml:2: sky.atmosphere_cache_max_mb: expected an integer in [0, 1048576], got -1");
}

// [atmosphere] sets every parameter of the medium in the units it names; the defaults are
// Bruneton's 2017 Earth; a value out of range, an unknown key and an inconsistent medium are
// named.
TEST(NodeConfig, AtmosphereMedium) {
  const skyig::atmosphere::Medium bruneton;
  EXPECT_TRUE(parseNodeConfig("", "empty").atmosphere.medium == bruneton);
  EXPECT_EQ(bruneton.bottomRadiusM, 6360e3);
  EXPECT_EQ(bruneton.miePhaseG, 0.8);
  const NodeConfig c = parseNodeConfig(
      "[atmosphere]\nground_radius_km = 6371\ntop_radius_km = 6471\nmie_extinction = 2e-5\nmie_phase_g = 0.7\n"
      "ozone_column_du = 350\nsun_angular_radius_deg = 0.25\nscattering_orders = 6\n",
      "a.toml");
  EXPECT_EQ(c.atmosphere.medium.bottomRadiusM, 6371e3);
  EXPECT_EQ(c.atmosphere.medium.topRadiusM, 6471e3);
  EXPECT_EQ(c.atmosphere.medium.mieExtinctionPerM, 2e-5);
  EXPECT_EQ(c.atmosphere.medium.miePhaseG, 0.7);
  EXPECT_EQ(c.atmosphere.medium.ozoneColumnDu, 350.0);
  EXPECT_NEAR(c.atmosphere.medium.sunAngularRadiusRad, 0.25 * skyig::atmosphere::kDegree, 1e-15);
  EXPECT_EQ(c.atmosphere.scatteringOrders, 6);
  EXPECT_EQ(c.atmosphere.medium.rayleighScaleHeightM, bruneton.rayleighScaleHeightM);  // untouched
  EXPECT_NE(errorOf("[atmosphere]\nmie_phase_g = 1.5\n").find("bad.toml:2: atmosphere.mie_phase_g: expected a number in"),
            std::string::npos);
  EXPECT_NE(errorOf("[atmosphere]\nmie_g = 0.7\n").find("atmosphere.mie_g: unknown key"), std::string::npos);
  EXPECT_NE(errorOf("[atmosphere]\ntop_radius_km = 6300\n").find("bad.toml: atmosphere:"), std::string::npos)
      << errorOf("[atmosphere]\ntop_radius_km = 6300\n");
}

// [channel.projector] names the calibration a channel is drawn for, relative to the
// configuration's folder; the channel's size is the projector's unless it gives one.
TEST(NodeConfig, ProjectorTableNamesTheCalibrationBesideTheFile) {
  const NodeConfig c = parseNodeConfig(
      "[[channel]]\nname = \"left\"\n[channel.projector]\nmpcdi = \"calib/dome.mpcdi\"\nregion = \"p1\"\n"
      "warp_values = \"offset\"\n"
      "[[channel]]\nname = \"right\"\nwidth = 800\nheight = 600\n[channel.projector]\nbourke_mesh = \"/abs/right.data\"\n"
      "[[channel]]\nname = \"plain\"\n",
      "/etc/skyig/dome.toml");
  const ProjectorSettings left = c.projectorOf("left");
  EXPECT_TRUE(left.enabled());
  EXPECT_EQ(left.mpcdi, "/etc/skyig/calib/dome.mpcdi");
  EXPECT_EQ(left.region, "p1");
  EXPECT_TRUE(left.warpOffsets);
  EXPECT_FALSE(left.sizeGiven);
  const ProjectorSettings right = c.projectorOf("right");
  EXPECT_EQ(right.bourkeMesh, "/abs/right.data");
  EXPECT_FALSE(right.warpOffsets);
  EXPECT_TRUE(right.sizeGiven);
  EXPECT_FALSE(c.projectorOf("plain").enabled());
  EXPECT_FALSE(parseNodeConfig("", "empty").projectorOf("front").enabled());
}

TEST(NodeConfig, ProjectorTableErrorsNameTheKey) {
  EXPECT_EQ(errorOf("[[channel]]\n[channel.projector]\nmpcdi = \"a.mpcdi\"\n"),
            "bad.toml:2: channel[0].projector.region: expected the MPCDI region this channel's projector shows");
  EXPECT_NE(errorOf("[[channel]]\n[channel.projector]\nmpcdi = \"a\"\nregion = \"r\"\nbourke_mesh = \"b\"\n")
                .find("channel[0].projector.mpcdi: expected either mpcdi"),
            std::string::npos);
  EXPECT_EQ(errorOf("[[channel]]\n[channel.projector]\nmpcdi = \"a\"\nregion = \"r\"\nwarp_values = \"relative\"\n"),
            "bad.toml:5: channel[0].projector.warp_values: expected \"absolute\" or \"offset\", got \"relative\"");
  EXPECT_NE(errorOf("[[channel]]\nwidth = 640\n[channel.projector]\nbourke_mesh = \"b\"\n").find("both width and height"),
            std::string::npos);
  EXPECT_NE(errorOf("[[channel]]\n[channel.projector]\nbourke_mesh = \"b\"\nregoin = \"r\"\n").find("unknown key"),
            std::string::npos);
}

// [channel.goggle] makes a channel a night-vision goggle: `on` switches it on from the start
// (the channel's band is then the goggle's class); without `on` it waits for the host's
// Sensor Control. A channel without the table keeps the eye's band and the default goggle.
TEST(NodeConfig, GoggleTableIsReadAndOnSetsTheChannelsBand) {
  const NodeConfig c = parseNodeConfig(
      "[[channel]]\nname = \"left\"\n[channel.goggle]\non = true\nclass = \"B\"\nphosphor = \"P45\"\n"
      "fov_deg = 51.5\ngain = 0.25\n"
      "[[channel]]\nname = \"right\"\n[channel.goggle]\n"
      "[[channel]]\nname = \"plain\"\n",
      "nvg.toml");
  ASSERT_EQ(c.channels.size(), 3u);
  const skyig::sky::ChannelConfig& left = c.channels[0];
  EXPECT_EQ(left.band, skyig::sky::SpectralBand::NvisClassB);
  EXPECT_TRUE(skyig::sky::isGoggle(left));
  EXPECT_EQ(left.goggle.nvisClass, skyig::sky::SpectralBand::NvisClassB);
  EXPECT_EQ(left.goggle.phosphor, skyig::sky::Phosphor::P45);
  EXPECT_EQ(left.goggle.fieldOfViewDeg, 51.5);
  EXPECT_FALSE(left.goggle.automaticGain);
  EXPECT_EQ(left.goggle.gain, 0.25);
  const skyig::sky::ChannelConfig& right = c.channels[1];  // a goggle the host can switch on
  EXPECT_FALSE(skyig::sky::isGoggle(right));
  EXPECT_EQ(right.goggle, skyig::sky::GoggleParams{});
  EXPECT_EQ(right.goggle.nvisClass, skyig::sky::SpectralBand::NvisClassA);
  EXPECT_EQ(right.goggle.phosphor, skyig::sky::Phosphor::P43);
  EXPECT_EQ(right.goggle.fieldOfViewDeg, 40.0);
  EXPECT_TRUE(right.goggle.automaticGain);
  EXPECT_FALSE(skyig::sky::isGoggle(c.channels[2]));
  const NodeConfig autoGain =
      parseNodeConfig("[[channel]]\n[channel.goggle]\non = true\ngain = \"auto\"\nfov_deg = 40\n", "nvg.toml");
  EXPECT_EQ(autoGain.channels[0].band, skyig::sky::SpectralBand::NvisClassA);
  EXPECT_TRUE(autoGain.channels[0].goggle.automaticGain);
  EXPECT_EQ(autoGain.channels[0].goggle.fieldOfViewDeg, 40.0);
  EXPECT_EQ(parseNodeConfig("[[channel]]\n[channel.goggle]\ngain = 1\n", "nvg.toml").channels[0].goggle.gain, 1.0);
}

// Each bad goggle value is refused with the file, the line, the key and the value.
TEST(NodeConfig, GoggleTableErrorsNameTheLineAndTheValue) {
  EXPECT_EQ(errorOf("[[channel]]\n[channel.goggle]\non = \"yes\"\n"),
            "bad.toml:3: channel[0].goggle.on: expected true or false, got 'yes'");
  EXPECT_EQ(errorOf("[[channel]]\n[channel.goggle]\nclass = \"C\"\n"),
            "bad.toml:3: channel[0].goggle.class: expected \"A\" or \"B\" (MIL-STD-3009 NVIS class), got \"C\"");
  EXPECT_EQ(errorOf("[[channel]]\n[channel.goggle]\nclass = 1\n"),
            "bad.toml:3: channel[0].goggle.class: expected \"A\" or \"B\", got 1");
  EXPECT_EQ(errorOf("[[channel]]\n[channel.goggle]\nphosphor = \"P20\"\n"),
            "bad.toml:3: channel[0].goggle.phosphor: expected \"P43\" or \"P45\", got \"P20\"");
  EXPECT_EQ(errorOf("[[channel]]\n[channel.goggle]\nfov_deg = 0\n"),
            "bad.toml:3: channel[0].goggle.fov_deg: expected a circular field of view in degrees in (0, 180), got 0");
  EXPECT_EQ(errorOf("[[channel]]\n[channel.goggle]\n\nfov_deg = 180.0\n"),
            "bad.toml:4: channel[0].goggle.fov_deg: expected a circular field of view in degrees in (0, 180), got 180.0");
  EXPECT_NE(errorOf("[[channel]]\n[channel.goggle]\nfov_deg = nan\n").find("bad.toml:3: channel[0].goggle.fov_deg: expected"),
            std::string::npos);
  EXPECT_EQ(errorOf("[[channel]]\n[channel.goggle]\ngain = 0\n"),
            "bad.toml:3: channel[0].goggle.gain: expected \"auto\" or a fraction of the maximum gain in (0, 1], got 0");
  EXPECT_EQ(errorOf("[[channel]]\n[channel.goggle]\ngain = 1.5\n"),
            "bad.toml:3: channel[0].goggle.gain: expected \"auto\" or a fraction of the maximum gain in (0, 1], got 1.5");
  EXPECT_EQ(errorOf("[[channel]]\n[channel.goggle]\ngain = \"manual\"\n"),
            "bad.toml:3: channel[0].goggle.gain: expected \"auto\" or a fraction of the maximum gain in (0, 1], got 'manual'");
  EXPECT_NE(errorOf("[[channel]]\n[channel.goggle]\nfov = 40\n").find("bad.toml:3: channel[0].goggle.fov: unknown key"),
            std::string::npos);
  EXPECT_NE(errorOf("[[channel]]\ngoggle = true\n").find("bad.toml:2: channel[0].goggle: expected a table [goggle]"),
            std::string::npos);
}
