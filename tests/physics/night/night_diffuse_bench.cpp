// Cost of the diffuse night pass (Milky Way, zodiacal light, airglow) at 1920x1200, wall clock
// after glFinish; with SKYIG_NIGHT_PNG_DIR set, PNGs of the Milky Way over a dark site to look at
// (the renderer's tone-reproduced frame, and the HDR frame exposed so the band is visible).
// Run: build/tests/physics/night/night_diffuse_bench [--benchmark_repetitions=5]
#include <benchmark/benchmark.h>

#include "sky/camera.h"
#include "render/gl/gl_context.h"
#include "render/image_io.h"
#include "render/passes/night/night_diffuse_pass.h"
#include "render/gl/render_target.h"
#include "render/sky_renderer.h"
#include "render/glsl/uniforms.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

using namespace skyig;
using namespace skyig::render;
using namespace skyig::sky;

namespace {

ObserverState darkSite() {
  ObserverState o;
  o.latitudeDeg = -30.0;  // a southern winter night: the galactic centre near the zenith
  o.longitudeDeg = 21.0;
  o.heightM = 1800.0;
  o.utc = {2026, 7, 15, 21.0 * 3600.0};
  o.attitude = {180.0, 35.0, 0.0};
  return o;
}

void writePngs(SkyRenderer& renderer, const std::string& dir) {
  const SkyState s = buildSkyState(darkSite(), SkyConditions{});
  ChannelConfig c;
  c.width = 960;
  c.height = 600;
  c.frustum = Frustum{60.0, 60.0, 40.0, 40.0};
  renderer.draw(s, c);
  writePng(dir + "/night-diffuse-tone.png", renderer.readDisplay(), c.display.gamma);
  const HdrImage hdr = renderer.readHdr();
  // Exposed so 2e-3 cd/m^2 is white: the band's structure, as a long photograph shows it.
  DisplayImage exposed{hdr.width, hdr.height, std::vector<std::uint8_t>(hdr.rgba.size())};
  for (std::size_t i = 0; i < hdr.rgba.size(); ++i)
    exposed.rgba[i] = i % 4 == 3 ? 255
                                 : static_cast<std::uint8_t>(255.0 * std::pow(std::clamp(hdr.rgba[i] / 2e-3f, 0.0f, 1.0f), 1.0 / 2.2) + 0.5);
  writePng(dir + "/night-diffuse-exposed.png", exposed, 2.2);
  std::printf("PNGs in %s: sun altitude %.1f deg\n", dir.c_str(), s.sunAltitude * 180.0 / 3.14159265358979);
}

void BM_NightDiffusePass1920x1200(benchmark::State& bench) {
  const SkyState s = buildSkyState(darkSite(), SkyConditions{});
  const auto sky = sky::nightDiffuseSky(s);
  NightDiffusePass pass;
  ChannelConfig c;
  c.width = 1920;
  c.height = 1200;
  FrameBlock b{};
  b.ndcToWorld = glm::mat4(glm::mat3(ndcToWorld(eyeToEnu(s.observer.attitude, c.offset), c.frustum)));
  b.viewport = glm::vec4(1920.0f, 1200.0f, 1.0f / 1920.0f, 1.0f / 1200.0f);
  UniformBuffer frame(SKYIG_BINDING_FRAME, sizeof(FrameBlock));
  frame.upload(b);
  frame.bind();
  RenderTarget target(c.width, c.height, GL_RGBA32F);
  target.bindForDrawing();
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  glBindVertexArray(vao);
  pass.draw(*sky);
  glFinish();
  for (auto _ : bench) {
    pass.draw(*sky);
    glFinish();
  }
  glDeleteVertexArrays(1, &vao);
  bench.counters["Mpixel/s"] = benchmark::Counter(1920.0 * 1200.0 * static_cast<double>(bench.iterations()) / 1e6,
                                                  benchmark::Counter::kIsRate);
}
BENCHMARK(BM_NightDiffusePass1920x1200)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  auto context = createHeadlessContext();
  if (const char* dir = std::getenv("SKYIG_NIGHT_PNG_DIR")) {
    SkyRenderer renderer;
    writePngs(renderer, dir);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
