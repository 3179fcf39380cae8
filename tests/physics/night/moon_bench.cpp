// Cost of the moon pass at 1920x1200 (wall clock after glFinish), and, with
// SKYIG_MOON_PNG_DIR set, PNGs of a crescent and a full moon to look at.
// Run: build/tests/physics/night/moon_bench [--benchmark_repetitions=5]
#include <benchmark/benchmark.h>

#include "sky/camera.h"
#include "render/gl/gl_context.h"
#include "render/image_io.h"
#include "render/passes/night/moon_pass.h"
#include "render/gl/render_target.h"
#include "render/sky_renderer.h"
#include "render/glsl/uniforms.h"
#include "tests/physics/night/moon_test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace skyig;
using namespace skyig::render;
using namespace skyig::sky;
using namespace skyig::sky::night;
using namespace skyig::sky::testing;

namespace {

ObserverState lookingAtMoon(ObserverState o) {
  const SkyState s = buildSkyState(o, SkyConditions{});
  o.attitude = {s.ephemeris->moon.azimuthRad / kDeg, s.ephemeris->moon.altitudeRefractedRad / kDeg, 0.0};
  return o;
}

// The renderer's frame and, beside it, the moon alone exposed so its brightest pixel is white.
void writeMoonPngs(SkyRenderer& renderer, const ObserverState& o, const std::string& stem) {
  const SkyState s = buildSkyState(lookingAtMoon(o), SkyConditions{});
  ChannelConfig c;
  c.width = 320;
  c.height = 240;
  c.frustum = Frustum{0.6, 0.6, 0.45, 0.45};
  renderer.draw(s, c);
  writePng(stem + "-tone.png", renderer.readDisplay(), c.display.gamma);
  const HdrImage hdr = renderer.readHdr();
  float peak = 0.0f;
  for (std::size_t i = 0; i < hdr.rgba.size(); ++i)
    if (i % 4 != 3) peak = std::max(peak, hdr.rgba[i]);
  DisplayImage exposed{hdr.width, hdr.height, std::vector<std::uint8_t>(hdr.rgba.size())};
  for (std::size_t i = 0; i < hdr.rgba.size(); ++i)
    exposed.rgba[i] = i % 4 == 3 ? 255
                                 : static_cast<std::uint8_t>(255.0 * std::pow(std::clamp(hdr.rgba[i] / peak, 0.0f, 1.0f), 1.0 / 2.2) + 0.5);
  writePng(stem + "-exposed.png", exposed, 2.2);
  std::printf("%s: %04d-%02d-%02d %05.0f s UTC, phase %.1f deg, altitude %.1f deg, %.3f lux\n", stem.c_str(), o.utc.year,
              o.utc.month, o.utc.day, o.utc.secondsOfDay, s.ephemeris->moon.phaseAngleRad / kDeg,
              s.ephemeris->moon.altitudeRefractedRad / kDeg, moonIlluminanceLux(s));
}

void BM_MoonPass1920x1200(benchmark::State& bench) {
  const std::optional<ObserverState> night = nightWithMoon(0.0, 20.0, 30.0);
  if (!night) {
    bench.SkipWithError("no full moon found");
    return;
  }
  const SkyState s = buildSkyState(lookingAtMoon(*night), SkyConditions{});
  ChannelConfig c;
  c.width = 1920;
  c.height = 1200;
  c.frustum = Frustum{30.0, 30.0, 19.8, 19.8};
  MoonPass pass;
  RenderTarget target(c.width, c.height, GL_RGBA32F);
  UniformBuffer frame(SKYIG_BINDING_FRAME, sizeof(FrameBlock));
  FrameBlock b{};
  const glm::dmat3 m = ndcToWorld(eyeToEnu(s.observer.attitude, c.offset), c.frustum);
  b.ndcToWorld = glm::mat4(glm::mat3(m));
  b.viewport = glm::vec4(1920.0f, 1200.0f, 1.0f / 1920.0f, 1.0f / 1200.0f);
  frame.upload(b);
  frame.bind();
  target.bindForDrawing();
  const MoonDisc d = *s.moonDisc;
  for (auto _ : bench) {
    pass.draw(d, m, c);
    glFinish();
  }
}
BENCHMARK(BM_MoonPass1920x1200)->Unit(benchmark::kMillisecond)->UseRealTime();

// The CPU half per frame: the disc's parameters (albedo normalisation) from a state.
void BM_MakeMoonDisc(benchmark::State& bench) {
  const std::optional<ObserverState> night = nightWithMoon(100.0, 150.0, 10.0);
  const SkyState s = buildSkyState(*night, SkyConditions{});
  for (auto _ : bench) benchmark::DoNotOptimize(makeMoonDisc(moonPlacement(*s.ephemeris), s.extinction));
}
BENCHMARK(BM_MakeMoonDisc)->Unit(benchmark::kMicrosecond);

}  // namespace

int main(int argc, char** argv) {
  const auto context = createHeadlessContext();
  if (const char* dir = std::getenv("SKYIG_MOON_PNG_DIR")) {
    SkyRenderer renderer;
    if (auto o = nightWithMoon(120.0, 140.0, 15.0)) writeMoonPngs(renderer, *o, std::string(dir) + "/moon-crescent");
    if (auto o = nightWithMoon(0.0, 8.0, 30.0)) writeMoonPngs(renderer, *o, std::string(dir) + "/moon-full");
    if (auto o = nightWithMoon(60.0, 100.0, 2.0)) {
      // The same moon low over the horizon: extinction reddens and refraction flattens it.
      for (int h = 0; h < 24 * 3; ++h) {
        ObserverState t = *o;
        t.utc.secondsOfDay = 0.0;
        t.utc.day += h / 24;
        t.utc.secondsOfDay = (h % 24) * 3600.0 + 1800.0;
        const SkyState s = buildSkyState(t, SkyConditions{});
        if (s.ephemeris->moon.altitudeRefractedRad > 1.0 * kDeg && s.ephemeris->moon.altitudeRefractedRad < 4.0 * kDeg &&
            s.ephemeris->sun.altitudeRad < -12.0 * kDeg) {
          writeMoonPngs(renderer, t, std::string(dir) + "/moon-low");
          break;
        }
      }
    }
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
