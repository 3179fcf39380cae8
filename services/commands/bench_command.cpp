#include "services/commands/bench_command.h"

#include "render/gl/gl_context.h"
#include "render/sky_renderer.h"
#include "services/commands/common_options.h"
#include "services/sky_data.h"

#include <glad/gl.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <memory>
#include <vector>

namespace skyig::services {

namespace {

struct BenchOptions {
  SkyOptions sky;
  int width = 1280;
  int height = 1024;
  int frames = 20;
  bool json = false;
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

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

int run(const BenchOptions& opt) {
  NodeConfig config = opt.sky.resolve();
  loadSkyData(config);
  sky::ChannelConfig channel = config.channels.front();
  channel.width = opt.width;
  channel.height = opt.height;
  const sky::SkyState state = sky::buildSkyState(config.observer, config.sky, opt.sky.sunOverride());
  const auto context = render::createHeadlessContext();
  render::SkyRenderer renderer;
  const bool gpuTimers = !context->info().softwareRenderer;
  const Timing sky = timePass(opt.frames, gpuTimers, [&] { renderer.drawSkyPass(state, channel); });
  const Timing full = timePass(opt.frames, gpuTimers, [&] { renderer.draw(state, channel); });
  const double pixels = static_cast<double>(channel.width) * channel.height;

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
  }
  return 0;
}

}  // namespace

void registerBenchCommand(CLI::App& app, int& exitCode) {
  auto opt = std::make_shared<BenchOptions>();
  CLI::App* c = app.add_subcommand("bench", "Time the sky pass of one channel, headless");
  opt->sky.add(*c);
  c->add_option("--width", opt->width, "Frame width")->check(CLI::Range(sky::kMinChannelSide, sky::kMaxChannelSide));
  c->add_option("--height", opt->height, "Frame height")->check(CLI::Range(sky::kMinChannelSide, sky::kMaxChannelSide));
  c->add_option("--frames", opt->frames, "Timed frames")->check(CLI::Range(1, 100000));
  c->add_flag("--json", opt->json, "Print the figures as JSON");
  c->callback([opt, &exitCode] { exitCode = run(*opt); });
}

}  // namespace skyig::services
