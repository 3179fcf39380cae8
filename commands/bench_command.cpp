#include "commands/bench_command.h"

#include "commands/bench_ratios.h"
#include "render/gl/gl_context.h"
#include "render/client/client_frame.h"
#include "render/sky_renderer.h"
#include "commands/common_options.h"
#include "node/config/sky_data.h"
#include "sky/client_light.h"
#include "node/host/node_stats.h"

#include <glad/gl.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace skyig::services {

namespace {

struct BenchOptions {
  SkyOptions sky;
  int width = 1280;
  int height = 1024;
  int frames = 20;
  std::string projectorSize = "1920x1200";
  bool json = false;
  bool ratios = false;
  int rounds = RatiosOptions{}.rounds;
  std::optional<int> llvmpipeThreads;
};

double cpuSeconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

struct Timing {
  std::vector<double> wallMs;
  std::vector<double> gpuMs;
  double cpuMs = 0.0;
};

template <typename Draw>
Timing timePass(int frames, bool gpuTimers, Draw draw) {
  Timing t;
  GLuint query = 0;
  if (gpuTimers) glGenQueries(1, &query);
  draw();  // warm-up: shader compilation and first-use allocations
  glFinish();
  const double cpu0 = cpuSeconds();
  for (int i = 0; i < frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    if (gpuTimers) glBeginQuery(GL_TIME_ELAPSED, query);
    draw();
    if (gpuTimers) glEndQuery(GL_TIME_ELAPSED);
    glFinish();
    t.wallMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    if (gpuTimers) {
      GLuint64 ns = 0;
      glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);
      t.gpuMs.push_back(static_cast<double>(ns) * 1e-6);
    }
  }
  t.cpuMs = (cpuSeconds() - cpu0) * 1e3 / frames;
  if (gpuTimers) glDeleteQueries(1, &query);
  return t;
}

// A projector for the warp-and-blend pass's timing: a gently curved warp over the whole channel
// image (a coarse map, as MPCDI's are), and a blend ramp with its black lift on the right fifth.
// Its cost does not depend on the values, only on the projector's pixels.
std::shared_ptr<const calibration::ProjectorCalibration> benchProjector(const sky::ChannelConfig& channel, int width,
                                                                        int height) {
  auto p = std::make_shared<calibration::ProjectorCalibration>();
  p->source = "bench projector";
  p->width = width;
  p->height = height;
  p->camera = {channel.offset, channel.frustum};
  p->cameraGiven = true;
  constexpr int kGrid = 64;
  p->warp = {kGrid, kGrid, 2, std::vector<float>(2 * kGrid * kGrid)};
  for (int y = 0; y < kGrid; ++y)
    for (int x = 0; x < kGrid; ++x) {
      const double u = x / (kGrid - 1.0), v = y / (kGrid - 1.0);
      p->warp.at(x, y, 0) = static_cast<float>(0.05 + 0.9 * u);
      p->warp.at(x, y, 1) = static_cast<float>(0.05 + 0.9 * v + 0.04 * (u - 0.5) * (u - 0.5));
    }
  p->alpha = {width, 1, 1, std::vector<float>(static_cast<std::size_t>(width), 1.0f)};
  p->beta = {width, 1, 1, std::vector<float>(static_cast<std::size_t>(width), 0.0f)};
  for (int x = width * 4 / 5; x < width; ++x) {
    const float t = static_cast<float>(x - width * 4 / 5) / static_cast<float>(width - width * 4 / 5);
    p->alpha.at(x, 0) = 1.0f - t;
    p->beta.at(x, 0) = 0.0f;
  }
  for (int x = 0; x < width * 4 / 5; ++x) p->beta.at(x, 0) = 0.001f;
  return p;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// A host's framebuffer of the channel's size (float colour, depth cleared to the far plane
// each frame: nothing drawn) and the host camera of the channel looking north, level: what
// ClientFrameRenderer::draw composites into (render/client/client_frame.h).
struct HostTarget {
  GLuint colour = 0, depth = 0, framebuffer = 0;
  glm::dmat4 view{1.0}, projection{0.0};
  HostTarget(const sky::ChannelConfig& channel) {
    glCreateTextures(GL_TEXTURE_2D, 1, &colour);
    glTextureStorage2D(colour, 1, GL_RGBA16F, channel.width, channel.height);
    glCreateTextures(GL_TEXTURE_2D, 1, &depth);
    glTextureStorage2D(depth, 1, GL_DEPTH_COMPONENT32F, channel.width, channel.height);
    glCreateFramebuffers(1, &framebuffer);
    glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, colour, 0);
    glNamedFramebufferTexture(framebuffer, GL_DEPTH_ATTACHMENT, depth, 0);
    // ENU -> eye: x east, y up, -z north.
    view[1] = glm::dvec4(0.0, 0.0, -1.0, 0.0);
    view[2] = glm::dvec4(0.0, 1.0, 0.0, 0.0);
    const double kDeg = 3.14159265358979323846 / 180.0, n = 1.0, f = 1.0e6;
    const double l = -n * std::tan(channel.frustum.leftDeg * kDeg), r = n * std::tan(channel.frustum.rightDeg * kDeg);
    const double b = -n * std::tan(channel.frustum.downDeg * kDeg), t = n * std::tan(channel.frustum.upDeg * kDeg);
    projection[0][0] = 2.0 * n / (r - l);
    projection[1][1] = 2.0 * n / (t - b);
    projection[2] = glm::dvec4((r + l) / (r - l), (t + b) / (t - b), -(f + n) / (f - n), -1.0);
    projection[3][2] = -2.0 * f * n / (f - n);
  }
  ~HostTarget() {
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &colour);
    glDeleteTextures(1, &depth);
  }
  HostTarget(const HostTarget&) = delete;
  HostTarget& operator=(const HostTarget&) = delete;
};

// CPU milliseconds of one call of `f`, the median of `n` after a first.
template <typename F>
double cpuMsPerCall(int n, F f) {
  f();
  std::vector<double> ms;
  for (int i = 0; i < n; ++i) {
    const auto start = std::chrono::steady_clock::now();
    f();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return median(ms);
}

int run(const BenchOptions& opt) {
  if (opt.llvmpipeThreads) pinLlvmpipeThreads(opt.llvmpipeThreads);  // before the GL context
  NodeConfig config = opt.sky.resolve();
  loadSkyData(config);
  sky::ChannelConfig channel = config.channels.front();
  channel.width = opt.width;
  channel.height = opt.height;
  sky::SkyState state = sky::buildSkyState(config.observer, config.sky, opt.sky.sunOverride());
  sky::mapForDisplays(state, {config.channels.front().display});  // as the node maps its states
  const auto context = render::createHeadlessContext();
  render::SkyRenderer renderer;
  const bool gpuTimers = !context->info().softwareRenderer;
  const Timing sky = timePass(opt.frames, gpuTimers, [&] { renderer.drawSkyPass(state, channel); });
  const Timing full = timePass(opt.frames, gpuTimers, [&] { renderer.draw(state, channel); });
  // The same channel as a class A night-vision goggle (sky::isGoggle): every night layer in the
  // goggle's band and the image intensifier instead of the eye's tone.
  sky::ChannelConfig goggle = channel;
  goggle.band = goggle.goggle.nvisClass;
  const Timing goggleFrame = timePass(opt.frames, gpuTimers, [&] { renderer.draw(state, goggle); });
  const double fullMs = gpuTimers ? median(full.gpuMs) : median(full.wallMs);
  const double goggleMs = gpuTimers ? median(goggleFrame.gpuMs) : median(goggleFrame.wallMs);
  const double pixels = static_cast<double>(channel.width) * channel.height;
  int projectorWidth = 0, projectorHeight = 0;
  parseSize(opt.projectorSize, projectorWidth, projectorHeight);
  const auto projector = benchProjector(channel, projectorWidth, projectorHeight);
  renderer.drawProjector(state, channel, projector);
  const Timing warp = timePass(opt.frames, gpuTimers, [&] { renderer.drawWarpBlendPass(projector); });
  const double warpMs = gpuTimers ? median(warp.gpuMs) : median(warp.wallMs);
  const double skyMs = gpuTimers ? median(sky.gpuMs) : median(sky.wallMs);
  // The sky in a host's frame: the composited draw (the whole channel plus the composite) and
  // the light a host queries per frame, on the CPU.
  render::ClientFrameRenderer hostRenderer;
  const HostTarget target(channel);
  const Timing composite = timePass(opt.frames, gpuTimers, [&] {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target.framebuffer);
    glClear(GL_DEPTH_BUFFER_BIT);
    hostRenderer.draw(state, target.view, target.projection, {0, 0, channel.width, channel.height});
  });
  const double compositeMs = gpuTimers ? median(composite.gpuMs) : median(composite.wallMs);
  const auto* model = state.conditions.atmosphere.get();
  // The node's whole frame: every channel of the configuration at its own size, one after the
  // other as `serve` draws them, from one state mapped for all their displays.
  sky::SkyState nodeState = sky::buildSkyState(config.observer, config.sky, opt.sky.sunOverride());
  std::vector<sky::DisplayParams> displays;
  for (const sky::ChannelConfig& c : config.channels) displays.push_back(c.display);
  sky::mapForDisplays(nodeState, displays);
  const Timing nodeFrame = timePass(opt.frames, gpuTimers, [&] {
    for (const sky::ChannelConfig& c : config.channels) renderer.draw(nodeState, c);
  });
  const std::vector<double>& nodeMs = gpuTimers ? nodeFrame.gpuMs : nodeFrame.wallMs;
  nlohmann::json perChannel = nlohmann::json::object();
  for (const sky::ChannelConfig& c : config.channels) {
    const Timing t = timePass(opt.frames, gpuTimers, [&] { renderer.draw(nodeState, c); });
    perChannel[c.name] = median(gpuTimers ? t.gpuMs : t.wallMs);
  }
  std::vector<double> sortedNodeMs = nodeMs;
  std::sort(sortedNodeMs.begin(), sortedNodeMs.end());
  const double lightMs = cpuMsPerCall(5, [&] { (void)sky::clientLight(state, model); });
  const double aerialMs =
      model ? cpuMsPerCall(20, [&] { (void)sky::clientAerialPerspective(state, *model, {0.0, 20000.0, -500.0}); }) : 0.0;

  nlohmann::json out = {
      {"renderer", context->info().renderer},
      {"gl_version", context->info().version},
      {"platform", context->info().platform},
      {"size", {channel.width, channel.height}},
      {"frames", opt.frames},
      {"timing", gpuTimers ? "GL timer queries (GPU time) and wall clock after glFinish"
                           : "wall clock after glFinish (software renderer: timer queries are meaningless)"},
      {"sky_pass_ms", gpuTimers ? median(sky.gpuMs) : median(sky.wallMs)},
      {"sky_pass_wall_ms", median(sky.wallMs)},
      {"sky_pass_ns_per_pixel", (gpuTimers ? median(sky.gpuMs) : median(sky.wallMs)) * 1e6 / pixels},
      {"sky_and_tone_ms", gpuTimers ? median(full.gpuMs) : median(full.wallMs)},
      {"sky_and_tone_wall_ms", median(full.wallMs)},
      {"process_cpu_ms_per_frame", full.cpuMs},
      {"sky_pass_process_cpu_ms_per_frame", sky.cpuMs},
      {"sky_pass_fastest_wall_ms", *std::min_element(sky.wallMs.begin(), sky.wallMs.end())},
      {"projector_size", {projectorWidth, projectorHeight}},
      {"warp_blend_pass_ms", warpMs},
      {"warp_blend_pass_wall_ms", median(warp.wallMs)},
      {"warp_blend_over_sky_pass", warpMs / skyMs},
      {"goggle_channel_ms", goggleMs},
      {"goggle_channel_process_cpu_ms_per_frame", goggleFrame.cpuMs},
      {"goggle_over_channel", goggleMs / fullMs},
      {"host_frame_ms", compositeMs},
      {"host_frame_over_sky_pass", compositeMs / skyMs},
      {"host_light_cpu_ms", lightMs},
      {"host_aerial_perspective_cpu_us", aerialMs * 1e3},
      {"node_frame",
       {{"channels", config.channels.size()},
        {"p50_ms", percentileOfSorted(sortedNodeMs, 0.5)},
        {"p99_ms", percentileOfSorted(sortedNodeMs, 0.99)},
        {"max_ms", sortedNodeMs.back()},
        {"channel_ms", perChannel}}},
  };
  if (opt.json) {
    std::printf("%s\n", out.dump(2).c_str());
  } else {
    std::printf("%s, %s, %dx%d, %d frames (%s)\n", context->info().renderer.c_str(), context->info().platform.c_str(),
                channel.width, channel.height, opt.frames, out["timing"].get<std::string>().c_str());
    std::printf("  sky pass:          %8.3f ms/frame  (%.1f ns/pixel; fastest frame %.3f ms; process CPU %.1f ms/frame)\n",
                out["sky_pass_ms"].get<double>(), out["sky_pass_ns_per_pixel"].get<double>(),
                out["sky_pass_fastest_wall_ms"].get<double>(), sky.cpuMs);
    std::printf("  sky + tone passes: %8.3f ms/frame  (process CPU %.1f ms/frame)\n",
                out["sky_and_tone_ms"].get<double>(), full.cpuMs);
    std::printf("  as a goggle:       %8.3f ms/frame  (the same channel as a class A goggle; %.2f times the eye's)\n",
                goggleMs, goggleMs / fullMs);
    std::printf("  warp and blend:    %8.3f ms/frame  (one %dx%d projector; %.2f times the sky pass)\n", warpMs,
                projectorWidth, projectorHeight, warpMs / skyMs);
    std::printf("  in a host's frame: %8.3f ms/frame  (the channel and the composite; %.2f times the sky pass)\n",
                compositeMs, compositeMs / skyMs);
    std::printf("  host light:        %8.3f ms/call of CPU  (sun, moon, ambient, SH9); aerial perspective %.1f us/point\n",
                lightMs, aerialMs * 1e3);
    std::printf("  the node's frame:  %8.3f ms/frame p50, p99 %.3f, max %.3f  (the configuration's %zu channel(s) at their own "
                "sizes:",
                percentileOfSorted(sortedNodeMs, 0.5), percentileOfSorted(sortedNodeMs, 0.99), sortedNodeMs.back(),
                config.channels.size());
    for (const auto& [name, ms] : perChannel.items()) std::printf(" %s %.3f", name.c_str(), ms.get<double>());
    std::printf(" ms)\n");
  }
  return 0;
}

}  // namespace

void registerBenchCommand(CLI::App& app, int& exitCode) {
  auto opt = std::make_shared<BenchOptions>();
  CLI::App* c = app.add_subcommand("bench", "Time the sky pass of one channel and a projector's warp-and-blend pass, headless");
  opt->sky.add(*c);
  c->add_option("--width", opt->width, "Frame width")->check(CLI::Range(sky::kMinChannelSide, sky::kMaxChannelSide));
  c->add_option("--height", opt->height, "Frame height")->check(CLI::Range(sky::kMinChannelSide, sky::kMaxChannelSide));
  c->add_option("--frames", opt->frames, "Timed frames (--ratios: per item and round, default 3)")->check(CLI::Range(1, 100000));
  c->add_option("--projector-size", opt->projectorSize,
                 "Projector resolution for the warp-and-blend pass's timing, WIDTHxHEIGHT (default 1920x1200)");
  c->add_flag("--json", opt->json, "Print the figures as JSON");
  CLI::Option* ratios = c->add_flag(
      "--ratios", opt->ratios,
      "Same-run ratios instead: the sky pass against its frozen reference, the day and night frames against it "
      "(process CPU per pixel, interleaved rounds; fixed scenes, one llvmpipe thread unless set)");
  for (const char* fixed : {"--utc", "--yaw", "--pitch", "--roll", "--sun-azimuth", "--sun-elevation", "--projector-size"})
    ratios->excludes(c->get_option(fixed));
  c->add_option("--rounds", opt->rounds, "--ratios: rounds, each timing every item in turn (default 5)")
      ->check(CLI::Range(1, 1000))
      ->needs(ratios);
  c->add_option("--llvmpipe-threads", opt->llvmpipeThreads,
                "LP_NUM_THREADS for llvmpipe, set before the GL context (0: llvmpipe's default); --ratios uses 1 "
                "unless this or LP_NUM_THREADS is given")
      ->check(CLI::Range(0, 1024));
  CLI::Option* frames = c->get_option("--frames");
  c->callback([opt, frames, &exitCode] {
    if (!opt->ratios) {
      exitCode = run(*opt);
      return;
    }
    RatiosOptions r;
    r.width = opt->width;
    r.height = opt->height;
    r.rounds = opt->rounds;
    if (frames->count() > 0) r.framesPerRound = opt->frames;  // else a few per round: the rounds are what repeats
    r.llvmpipeThreads = opt->llvmpipeThreads;
    r.json = opt->json;
    exitCode = runRatiosBench(opt->sky.resolve(), r);
  });
}

}  // namespace skyig::services
