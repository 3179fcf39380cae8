// Google Benchmark (not a ctest test): the star and planet passes at 1920x1200 on this machine's
// GL (llvmpipe where there is no GPU), wall clock after glFinish, and the worker's per-state
// star field. The displayed-star pass reads a night sky's HDR image and maps through the
// Tumblin-Rushmeier branch of the tone block (the histogram curve costs the same lookup).
#include "sky/camera.h"
#include "render/gl/gl_context.h"
#include "render/gl/gl_program.h"
#include "render/gl/render_target.h"
#include "render/passes/night/star_pass.h"
#include "render/glsl/uniforms.h"
#include "tests/physics/night/star_test_support.h"

#include <benchmark/benchmark.h>

#include <memory>

using namespace skyig;
using namespace skyig::render;
using namespace skyig::sky;

namespace {

const ephemeris::SkyEphemeris& night() {
  static const ephemeris::SkyEphemeris sky = [] {
    ephemeris::Observer o;
    o.latitudeRad = 47.26 * night_testing::kDeg;
    o.longitudeRad = 11.34 * night_testing::kDeg;
    return ephemeris::computeEphemeris({2026, 1, 15, 21 * 3600.0}, o);
  }();
  return sky;
}

const night::StarCatalogue& catalogue() {
  static const night::StarCatalogue c(night_testing::catalogue(), {2026, 1, 15, 0.0});
  return c;
}

const atmosphere::ExtinctionProfile& extinction() {
  static const atmosphere::ExtinctionProfile p(atmosphere::Medium{}, 581.0);
  return p;
}

std::shared_ptr<const night::StarField> field(double timeS) {
  night::StarFieldOptions o;
  o.timeS = timeS;
  return std::make_shared<const night::StarField>(night::buildStarField(&catalogue(), night(), extinction(), o));
}

// `reupload`: a new state every frame (its field uploaded each time), else the same state.
void starPass(benchmark::State& state, bool reupload) {
  const auto context = createHeadlessContext();
  StarPass pass;
  UniformBuffer frame(SKYIG_BINDING_FRAME, sizeof(FrameBlock));
  constexpr int kW = 1920, kH = 1200;
  const glm::dmat3 m = ndcToWorld(eyeToEnu(Attitude{180.0, 45.0, 0.0}, Attitude{}), Frustum{30, 30, 18.75, 18.75});
  FrameBlock block{};
  block.ndcToWorld = glm::mat4(glm::mat3(m));
  block.viewport = glm::vec4(kW, kH, 1.0f / kW, 1.0f / kH);
  frame.upload(block);
  frame.bind();
  RenderTarget target(kW, kH, GL_RGBA32F);
  target.bindForDrawing();
  // Two states to alternate between (built outside the timing: BM_BuildStarField times that).
  const std::shared_ptr<const night::StarField> fields[2] = {field(0.0), field(0.016)};
  auto f = fields[0];
  int next = 0;
  int inView = 0;
  const glm::dmat3 inverse = glm::inverse(m);
  for (const auto* list : {&f->stars, &f->planets})
    for (const auto& s : *list) {
      const glm::dvec3 p = inverse * s.direction;
      inView += p.z > 0.0 && std::abs(p.x / p.z) <= 1.0 && std::abs(p.y / p.z) <= 1.0;
    }
  for (auto _ : state) {
    if (reupload) f = fields[next ^= 1];
    pass.draw(f, m);
    glFinish();
  }
  state.counters["sources"] = static_cast<double>(f->stars.size() + f->planets.size());
  state.counters["in_view"] = inView;
  state.SetLabel(context->info().renderer);
}

// The displayed-star pass (StarPass::drawDisplayed): per star, the sky behind it, both
// thresholds and the tone mapping of the background in the vertex shader; a PSF of 2 arcmin.
void BM_DisplayedStarPass1920x1200(benchmark::State& state) {
  const auto context = createHeadlessContext();
  StarPass pass;
  UniformBuffer frame(SKYIG_BINDING_FRAME, sizeof(FrameBlock));
  UniformBuffer tone(SKYIG_BINDING_TONE, sizeof(ToneBlock));
  constexpr int kW = 1920, kH = 1200;
  const glm::dmat3 m = ndcToWorld(eyeToEnu(Attitude{180.0, 45.0, 0.0}, Attitude{}), Frustum{30, 30, 18.75, 18.75});
  FrameBlock block{};
  block.ndcToWorld = glm::mat4(glm::mat3(m));
  block.viewport = glm::vec4(kW, kH, 1.0f / kW, 1.0f / kH);
  frame.upload(block);
  frame.bind();
  ToneBlock t{};
  t.display = glm::vec4(100.0f, 0.1f, 2.2f, 10.0f);
  t.adaptation = glm::vec4(2e-4f, 1.0f, 1.0f, 0.0f);
  tone.upload(t);
  tone.bind();
  RenderTarget sky(kW, kH, GL_RGBA32F);  // a dark night sky behind every star
  const float night[4] = {2e-4f, 2e-4f, 2e-4f, 1.0f};
  glClearNamedFramebufferfv(sky.framebuffer(), GL_COLOR, 0, night);
  RenderTarget target(kW, kH, GL_RGBA16F);
  target.bindForDrawing();
  const auto f = field(0.0);
  for (auto _ : state) {
    pass.drawDisplayed(f, m, sky.texture());
    glFinish();
  }
  state.SetLabel(context->info().renderer);
}

void BM_StarPass1920x1200(benchmark::State& state) { starPass(state, false); }
void BM_StarPass1920x1200NewStateEachFrame(benchmark::State& state) { starPass(state, true); }

void BM_BuildStarField(benchmark::State& state) {
  double t = 0.0;
  for (auto _ : state) benchmark::DoNotOptimize(field(t += 0.016));
}

}  // namespace

BENCHMARK(BM_StarPass1920x1200)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DisplayedStarPass1920x1200)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_StarPass1920x1200NewStateEachFrame)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_BuildStarField)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
