#include "commands/bench_ratios.h"

#include "ephemeris/time.h"
#include "render/gl/gl_context.h"
#include "render/passes/sky/reference_sky_pass.h"
#include "render/sky_renderer.h"
#include "node/config/sky_data.h"
#include "physics/common/units.h"
#include "physics/weather/cloud_layer.h"
#include "physics/weather/fog_layer.h"
#include "physics/weather/precipitation.h"

#include <glad/gl.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

namespace skyig::services {

namespace {

// Process CPU time (every thread: llvmpipe's rasteriser threads too), seconds.
double processCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The scenes, at the configuration's place (Innsbruck by default): a summer afternoon, 15:00
// UTC, with the sun and the half moon from the ephemeris, so the night passes run in daylight as
// they do in the node; a full-moon night looking at the moon; a moonless night (new moon, below
// the horizon) looking south. The moon block of the sky pass runs in all three (the moon lights
// the tables from below the horizon too).
struct Scene {
  const char* key;
  const char* what;
  const char* utc;
  double yawDeg, pitchDeg;
};
constexpr Scene kDay{"day", "15:00 UTC, facing the afternoon sun, the half moon up", "2026-06-21T15:00:00Z", 262.0, 20.0};
constexpr Scene kMoonlit{"moonlit_night", "full moon, facing it", "2026-01-03T21:00:00Z", 108.0, 30.0};
constexpr Scene kMoonless{"moonless_night", "new moon below the horizon, facing south", "2026-01-18T21:00:00Z", 180.0, 30.0};

sky::SkyState buildScene(const NodeConfig& config, const Scene& scene) {
  sky::ObserverState observer = config.observer;
  observer.utc = *ephemeris::parseIso8601Utc(scene.utc);
  observer.attitude = {scene.yawDeg, scene.pitchDeg, 0.0};
  // Mapped for the channel's display as the node maps its states: the same layers drawn.
  sky::SkyState s = sky::buildSkyState(observer, config.sky);
  sky::mapForDisplays(s, {config.channels.front().display});
  return s;
}

struct Stats {
  double min = 0.0, median = 0.0, max = 0.0;
};

Stats stats(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return {v.front(), n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]), v.back()};
}

nlohmann::json toJson(const Stats& s) { return {{"min", s.min}, {"median", s.median}, {"max", s.max}}; }

// One thing timed: a pass or a frame of one scene.
struct Item {
  const char* key;
  const char* what;
  const Scene* scene;
  std::function<void()> draw;
  std::vector<double> nsPerPixel;  // one per round
};

// A ratio of two items, per round (numerator and denominator from the same round).
struct Ratio {
  const char* key;
  const char* what;
  const char *numerator, *denominator;  // Item keys
  double factor = 1.0;
};

}  // namespace

std::string pinLlvmpipeThreads(const std::optional<int>& requested) {
  if (requested) {
    if (*requested == 0) {
      ::unsetenv("LP_NUM_THREADS");
      return "llvmpipe's default (--llvmpipe-threads 0)";
    }
    ::setenv("LP_NUM_THREADS", std::to_string(*requested).c_str(), 1);
    return std::to_string(*requested) + " (--llvmpipe-threads)";
  }
  if (const char* set = std::getenv("LP_NUM_THREADS")) return std::string(set) + " (LP_NUM_THREADS of the environment)";
  ::setenv("LP_NUM_THREADS", "1", 1);
  return "1 (set by the bench; --llvmpipe-threads N or LP_NUM_THREADS to change)";
}

namespace {

// The states the bench draws, built once before anything is timed.
struct Scenes {
  sky::SkyState day, moonlit, moonless;
  // The day with the same sun forced (no ephemeris: no moon, no night passes): the frame that
  // drawing only what is visible can reach.
  sky::SkyState dayForced;
  // The moonless night's sky pass against the reference does the reference's work: the sun's
  // sky too, which the frame leaves out once night has fallen (sky/shown_layers.h).
  sky::SkyState moonlessSunlit;
  // The day in the worst weather the sky pass composes: all three layers at once, the camera
  // inside the haze and the dust (the absorbing layer's per-channel solution) and above the fog.
  sky::SkyState dayWeather;
  // The day under a full stratus deck above the eye (800-1200 m), and under broken cumulus (50 %,
  // 1200-2000 m): the sky pass's cloud variants (docs/clouds.md).
  sky::SkyState dayOvercast, dayCumulus;
  const sky::SkyState& of(const Scene* s) const { return s == &kDay ? day : s == &kMoonlit ? moonlit : moonless; }
};

Scenes buildScenes(const NodeConfig& config) {
  Scenes s{buildScene(config, kDay), buildScene(config, kMoonlit), buildScene(config, kMoonless), {}, {}, {}, {}, {}};
  s.dayForced = sky::buildSkyState(s.day.observer, config.sky,
                                   sky::SunOverride{s.day.sunAzimuth * kDegPerRad, s.day.sunAltitude * kDegPerRad});
  sky::mapForDisplays(s.dayForced, {config.channels.front().display});
  s.moonlessSunlit = s.moonless;
  s.moonlessSunlit.shown.sunlitSky = true;
  sky::SkyConditions weather = config.sky;
  weather.haze = weather::hazeBelowTables(2.5, 1200.0);
  weather.fog = {0.0, 200.0, 0.4};
  weather.precipitation = weather::precipitationLayer(weather::Precipitation::dust, 0.0, 1500.0, 0.0, 2, 1.0);
  s.dayWeather = sky::buildSkyState(s.day.observer, weather);
  sky::mapForDisplays(s.dayWeather, {config.channels.front().display});
  auto underCloud = [&](const char* spec) {
    sky::SkyConditions c = config.sky;
    c.clouds[0] = weather::parseCloudSpec(spec);
    sky::SkyState state = sky::buildSkyState(s.day.observer, c);
    sky::mapForDisplays(state, {config.channels.front().display});
    return state;
  };
  s.dayOvercast = underCloud("stratus:800:400:100");
  s.dayCumulus = underCloud("cumulus:1200:800:50");
  return s;
}

// The renderers the items draw with: the live frame, the frozen reference pass, and the frame as
// it was drawn before the sky pass mapped its own pixels (the tone pass over every pixel after
// the others).
struct Renderers {
  render::SkyRenderer live, reference, toneEverywhere;
  Renderers() {
    reference.usePhysicalSkyPass(render::makeReferenceSkyPass());
    toneEverywhere.setToneFolding(false);
  }
};

std::vector<Item> benchItems(Renderers& r, const Scenes& s, const sky::ChannelConfig& channel) {
  return {
      {"reference_sky_pass_day", "reference sky pass", &kDay, [&] { r.reference.drawSkyPass(s.day, channel); }, {}},
      {"sky_pass_day", "sky pass", &kDay, [&] { r.live.drawSkyPass(s.day, channel); }, {}},
      {"sky_pass_weather_day", "sky pass under haze (2.5 km), a 200 m fog and a dust storm", &kDay,
       [&] { r.live.drawSkyPass(s.dayWeather, channel); }, {}},
      {"sky_pass_overcast_day", "sky pass under a full stratus deck, 800-1200 m", &kDay,
       [&] { r.live.drawSkyPass(s.dayOvercast, channel); }, {}},
      {"sky_pass_cumulus_day", "sky pass under broken cumulus (50 %), 1200-2000 m", &kDay,
       [&] { r.live.drawSkyPass(s.dayCumulus, channel); }, {}},
      {"sky_pass_mapped_day", "sky pass mapping its pixels, as in the frame", &kDay,
       [&] { r.live.drawMappedSkyPass(s.day, channel); }, {}},
      {"day_frame", "day frame (every pass + tone)", &kDay, [&] { r.live.draw(s.day, channel); }, {}},
      {"day_frame_sun_forced", "day frame, sun forced (no night)", &kDay, [&] { r.live.draw(s.dayForced, channel); }, {}},
      {"day_frame_tone_over_every_pixel", "day frame, the tone pass over every pixel", &kDay,
       [&] { r.toneEverywhere.draw(s.day, channel); }, {}},
      {"moonlit_night_frame", "night frame (every pass + tone)", &kMoonlit, [&] { r.live.draw(s.moonlit, channel); }, {}},
      {"moonless_night_frame", "night frame (every pass + tone)", &kMoonless, [&] { r.live.draw(s.moonless, channel); }, {}},
      {"reference_sky_pass_moonless_night", "reference sky pass", &kMoonless,
       [&] { r.reference.drawSkyPass(s.moonless, channel); }, {}},
      {"sky_pass_moonless_night", "sky pass, the sun's sky drawn", &kMoonless,
       [&] { r.live.drawSkyPass(s.moonlessSunlit, channel); }, {}},
  };
}

const std::vector<Ratio>& benchRatios() {
  static const std::vector<Ratio> kRatios = {
      {"sky_pass_over_reference", "sky pass / reference (day)", "sky_pass_day", "reference_sky_pass_day"},
      {"sky_pass_over_reference_moonless_night", "sky pass / reference (moonless night)", "sky_pass_moonless_night",
       "reference_sky_pass_moonless_night"},
      {"day_frame_over_sky_pass", "day frame / sky pass", "day_frame", "sky_pass_day"},
      {"weather_sky_pass_over_sky_pass", "sky pass under haze, fog and dust / sky pass (clear)", "sky_pass_weather_day",
       "sky_pass_day"},
      {"overcast_sky_pass_over_sky_pass", "sky pass under a stratus deck / sky pass (clear)", "sky_pass_overcast_day",
       "sky_pass_day"},
      {"cumulus_sky_pass_over_sky_pass", "sky pass under broken cumulus / sky pass (clear)", "sky_pass_cumulus_day",
       "sky_pass_day"},
      {"day_frame_over_mapped_sky_pass", "day frame / sky pass mapping its pixels, as in the frame", "day_frame", "sky_pass_mapped_day"},
      {"day_frame_over_sun_forced_day_frame", "day frame / day frame with the sun forced", "day_frame",
       "day_frame_sun_forced"},
      {"day_frame_over_tone_over_every_pixel", "day frame / the same with the tone pass over every pixel", "day_frame",
       "day_frame_tone_over_every_pixel"},
      {"moonlit_night_frame_over_day_frame", "moonlit night frame / day frame", "moonlit_night_frame", "day_frame"},
      {"moonless_night_frame_over_day_frame", "moonless night frame / day frame", "moonless_night_frame", "day_frame"},
      {"bruneton_2017_estimate", "\u2248 x of Bruneton 2017 (sky pass / reference x 0.38)", "sky_pass_day",
       "reference_sky_pass_day", render::kReferenceOverBruneton2017},
  };
  return kRatios;
}

// Every item once (compiling its programs), then `rounds` rounds of every item, ABAB... and
// BABA... in the next round, so a slow drift of the machine's load weighs on every item alike.
void timeRounds(std::vector<Item>& items, const sky::ChannelConfig& channel, const RatiosOptions& opt) {
  for (Item& item : items) item.draw();
  glFinish();
  const double pixels = static_cast<double>(channel.width) * channel.height;
  for (int round = 0; round < opt.rounds; ++round) {
    std::fprintf(stderr, "bench: round %d of %d (%zu items x %d frame(s), %dx%d)...\n", round + 1, opt.rounds, items.size(),
                 opt.framesPerRound, channel.width, channel.height);
    for (std::size_t k = 0; k < items.size(); ++k) {
      Item& item = items[round % 2 ? items.size() - 1 - k : k];
      glFinish();
      const double cpu0 = processCpuSeconds();
      for (int f = 0; f < opt.framesPerRound; ++f) item.draw();
      glFinish();
      item.nsPerPixel.push_back((processCpuSeconds() - cpu0) * 1e9 / (pixels * opt.framesPerRound));
    }
  }
}

// Each ratio over the rounds, its numerator and denominator from the same round.
std::vector<Stats> ratioStats(const std::vector<Item>& items, int rounds) {
  const auto itemOf = [&items](const char* key) -> const Item& {
    return *std::find_if(items.begin(), items.end(), [key](const Item& i) { return std::string(i.key) == key; });
  };
  std::vector<Stats> out;
  for (const Ratio& r : benchRatios()) {
    std::vector<double> perRound;
    for (std::size_t round = 0; round < static_cast<std::size_t>(rounds); ++round)
      perRound.push_back(r.factor * itemOf(r.numerator).nsPerPixel[round] / itemOf(r.denominator).nsPerPixel[round]);
    out.push_back(stats(perRound));
  }
  return out;
}

constexpr const char* kBrunetonNote =
    "0.38 is the reference's measured ratio to Bruneton & Neyret's 2017 demo pass (process CPU per pixel, "
    "interleaved rounds on the 2-core development machine's llvmpipe, one thread, 1280x1024); the product is "
    "an estimate, not a measurement of Bruneton's pass";

// What one run measured, whichever form it is printed in.
struct Report {
  const render::GlInfo& gl;
  const std::string& threads;
  const sky::ChannelConfig& channel;
  const RatiosOptions& opt;
  const std::string& tables;
  const Scenes& scenes;
  const std::vector<Item>& items;
  const std::vector<Stats>& ratios;
};

nlohmann::json reportJson(const Report& r) {
  nlohmann::json out = {
      {"mode", "ratios"},
      {"renderer", r.gl.renderer},
      {"gl_version", r.gl.version},
      {"platform", r.gl.platform},
      {"llvmpipe_threads", r.threads},
      {"size", {r.channel.width, r.channel.height}},
      {"rounds", r.opt.rounds},
      {"frames_per_round", r.opt.framesPerRound},
      {"tables", r.tables},
      {"reference", render::kReferenceSkyFragment},
      {"timing", "process CPU time per pixel (every thread), glFinish around each item; items interleaved in "
                 "every round, in reverse order every other round; ratios of the same round"},
      {"bruneton_2017_note", kBrunetonNote},
  };
  if (!r.gl.softwareRenderer)
    out["warning"] = "a GPU renders here: process CPU time is the driver's, not the GPU's (skyig bench without "
                     "--ratios times the passes with GL timer queries)";
  for (const Scene* s : {&kDay, &kMoonlit, &kMoonless}) {
    const sky::SkyState& state = r.scenes.of(s);
    out["scenes"][s->key] = {{"what", s->what},
                             {"utc", s->utc},
                             {"yaw_deg", s->yawDeg},
                             {"pitch_deg", s->pitchDeg},
                             {"sun_altitude_deg", state.sunAltitude * kDegPerRad},
                             {"moon_altitude_deg", std::asin(std::clamp(state.moonDirection.z, -1.0, 1.0)) * kDegPerRad}};
  }
  for (const Item& item : r.items) {
    out["ns_per_pixel"][item.key] = toJson(stats(item.nsPerPixel));
    out["ns_per_pixel"][item.key]["rounds"] = item.nsPerPixel;
  }
  for (std::size_t i = 0; i < benchRatios().size(); ++i) out["ratios"][benchRatios()[i].key] = toJson(r.ratios[i]);
  return out;
}

// Width in characters: the "\u2248" of a label is 3 bytes and one character.
int characters(const char* text) {
  int n = 0;
  for (const char* c = text; *c; ++c) n += (static_cast<unsigned char>(*c) & 0xC0) != 0x80 ? 1 : 0;
  return n;
}

void printItemTable(const std::vector<Item>& items) {
  int whatWidth = 4;  // the column as wide as its longest label
  for (const Item& item : items) whatWidth = std::max(whatWidth, static_cast<int>(std::strlen(item.what)));
  std::printf("| %-*s | %-15s | %26s |\n", whatWidth, "what", "scene", "ns/pixel min / median / max");
  std::printf("| %-*s | %-15s | %26s |\n", whatWidth, "---", "---", "---");
  for (const Item& item : items) {
    const Stats s = stats(item.nsPerPixel);
    std::printf("| %-*s | %-15s | %8.1f / %6.1f / %6.1f |\n", whatWidth, item.what, item.scene->key, s.min, s.median,
                s.max);
  }
}

void printRatioTable(const std::vector<Stats>& ratioStats) {
  const std::vector<Ratio>& ratios = benchRatios();
  int ratioWidth = 17;
  for (const Ratio& r : ratios) ratioWidth = std::max(ratioWidth, characters(r.what));
  std::printf("\n| %-*s | %22s |\n", ratioWidth, "ratio, same round", "min / median / max");
  std::printf("| %-*s | %22s |\n", ratioWidth, "---", "---");
  for (std::size_t i = 0; i < ratios.size(); ++i)
    std::printf("| %-*s | %6.2f / %6.2f / %6.2f |\n",
                ratioWidth + static_cast<int>(std::strlen(ratios[i].what)) - characters(ratios[i].what), ratios[i].what,
                ratioStats[i].min, ratioStats[i].median, ratioStats[i].max);
}

void printReport(const Report& r, bool warning) {
  std::printf("skyig bench --ratios: %s, %s, %dx%d, %d round(s) x %d frame(s) per item, %s tables\n", r.gl.renderer.c_str(),
              r.gl.platform.c_str(), r.channel.width, r.channel.height, r.opt.rounds, r.opt.framesPerRound,
              r.tables.c_str());
  std::printf("LP_NUM_THREADS %s\n", r.threads.c_str());
  std::printf("process CPU time per pixel, items interleaved in each round; reference: %s\n\n",
              render::kReferenceSkyFragment);
  printItemTable(r.items);
  printRatioTable(r.ratios);
  std::printf("\nScenes (the configuration's place, its first channel's frustum):\n");
  for (const Scene* s : {&kDay, &kMoonlit, &kMoonless})
    std::printf("  %-15s %s, yaw %.0f, pitch %.0f: %s\n", s->key, s->utc, s->yawDeg, s->pitchDeg, s->what);
  std::printf("%s.\n", kBrunetonNote);
  if (warning)
    std::printf("Warning: a GPU renders here: process CPU time is the driver's, not the GPU's (skyig bench without "
                "--ratios times the passes with GL timer queries).\n");
}

}  // namespace

int runRatiosBench(NodeConfig config, const RatiosOptions& opt) {
  // Before anything makes a GL context (the tables' precompute may): llvmpipe reads it once.
  const std::string threads = pinLlvmpipeThreads(opt.llvmpipeThreads);
  if (config.sky.model != sky::SkyModel::Physical)
    throw ConfigError("bench --ratios: the reference is the physical sky's pass; the configuration's sky model is not physical");
  std::fprintf(stderr, "bench: loading the %s tables and the star catalogue (a precompute the first time)...\n",
               config.atmosphere.tables.c_str());
  config.observer.utc = *ephemeris::parseIso8601Utc(kDay.utc);  // the catalogue's epoch
  loadSkyData(config);
  const Scenes scenes = buildScenes(config);
  sky::ChannelConfig channel = config.channels.front();
  channel.width = opt.width;
  channel.height = opt.height;

  const auto context = render::createHeadlessContext();
  Renderers renderers;
  std::vector<Item> items = benchItems(renderers, scenes, channel);
  std::fprintf(stderr, "bench: %s, LP_NUM_THREADS %s; compiling the passes (one frame of each)...\n",
               context->info().renderer.c_str(), threads.c_str());
  timeRounds(items, channel, opt);
  const std::vector<Stats> ratios = ratioStats(items, opt.rounds);
  const Report report{context->info(), threads, channel, opt, config.atmosphere.tables, scenes, items, ratios};
  if (opt.json) std::printf("%s\n", reportJson(report).dump(2).c_str());
  else printReport(report, !context->info().softwareRenderer);
  return 0;
}

}  // namespace skyig::services
