// The diffuse night pass on the GL path (llvmpipe where there is no GPU) against its CPU twin
// (physics/night/night_diffuse.h), pixel by pixel, and its output finite everywhere.
#include "sky/camera.h"
#include "render/gl/gl_context.h"
#include "render/gl/gl_program.h"
#include "render/passes/night/night_diffuse_pass.h"
#include "render/gl/render_target.h"
#include "sky/sky_state.h"
#include "render/glsl/uniforms.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

using namespace skyig;
using namespace skyig::render;
using namespace skyig::sky;

namespace {

struct Rendered {
  int width, height;
  std::vector<float> rgba;  // GL rows: bottom first
  glm::dvec3 at(int x, int yTop) const {
    const float* p = &rgba[(static_cast<std::size_t>(height - 1 - yTop) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4];
    return {p[0], p[1], p[2]};
  }
};

class NightDiffuseGl : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    context_ = createHeadlessContext().release();
    pass_ = new NightDiffusePass();
    glCreateVertexArrays(1, &vao_);
  }
  static void TearDownTestSuite() {
    glDeleteVertexArrays(1, &vao_);
    delete pass_;
    delete context_;
  }

  static Rendered render(const night::NightDiffuseSky& sky, const glm::dmat3& ndcToWorldM, int w, int h) {
    FrameBlock b{};
    b.ndcToWorld = glm::mat4(glm::mat3(ndcToWorldM));
    b.viewport = glm::vec4(static_cast<float>(w), static_cast<float>(h), 1.0f / static_cast<float>(w), 1.0f / static_cast<float>(h));
    UniformBuffer frame(SKYIG_BINDING_FRAME, sizeof(FrameBlock));
    frame.upload(b);
    frame.bind();
    RenderTarget target(w, h, GL_RGBA32F);
    target.bindForDrawing();
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(target.framebuffer(), GL_COLOR, 0, zero);
    glBindVertexArray(vao_);
    pass_->draw(sky);
    Rendered r{w, h, std::vector<float>(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4)};
    glGetTextureImage(target.texture(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(r.rgba.size() * sizeof(float)), r.rgba.data());
    return r;
  }

  static SkyState darkSite() {
    ObserverState o;
    o.latitudeDeg = -30.0;
    o.longitudeDeg = 21.0;
    o.heightM = 1800.0;
    o.utc = {2026, 7, 15, 21.0 * 3600.0};  // Sagittarius high, after dusk
    return buildSkyState(o, SkyConditions{});
  }

  static inline GlContext* context_ = nullptr;
  static inline NightDiffusePass* pass_ = nullptr;
  static inline GLuint vao_ = 0;
};

double y709(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

}  // namespace

// A narrow view (0.1 deg a pixel: the map's full resolution, no mip level between them) on the
// Milky Way near the horizon: GPU and CPU agree within the half-float texture and float maths.
TEST_F(NightDiffuseGl, MatchesTheCpuPerPixel) {
  const SkyState s = darkSite();
  const auto sky = sky::nightDiffuseSky(s);
  ASSERT_TRUE(sky.has_value());
  constexpr int kW = 64, kH = 48;
  for (const Attitude& look : {Attitude{135.0, 60.0, 0.0}, Attitude{250.0, 8.0, 10.0}, Attitude{20.0, 30.0, 0.0}}) {
    const glm::dmat3 m = ndcToWorld(eyeToEnu(look, Attitude{}), Frustum{3.2, 3.2, 2.4, 2.4});
    const Rendered r = render(*sky, m, kW, kH);
    for (int y = 2; y < kH; y += 9)
      for (int x = 3; x < kW; x += 11) {
        const glm::dvec3 cpu = night::nightDiffuseRadiance(*sky, pixelRay(m, x, y, kW, kH)).total();
        const glm::dvec3 gpu = r.at(x, y);
        EXPECT_NEAR(y709(gpu), y709(cpu), 0.03 * y709(cpu) + 1e-8) << "yaw " << look.yawDeg << " pixel " << x << "," << y;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(gpu[c], cpu[c], 0.05 * cpu[c] + 2e-7);
      }
  }
}

// A fisheye-wide frustum over the whole sky and below the horizon: finite, non-negative, black
// on the ground, and the night's light above it.
TEST_F(NightDiffuseGl, FiniteEverywhereAndDarkBelowTheHorizon) {
  const SkyState s = darkSite();
  const auto sky = sky::nightDiffuseSky(s);
  ASSERT_TRUE(sky.has_value());
  constexpr int kW = 96, kH = 96;
  const glm::dmat3 m = ndcToWorld(eyeToEnu(Attitude{0.0, 0.0, 0.0}, Attitude{}), Frustum{80.0, 80.0, 80.0, 80.0});
  const Rendered r = render(*sky, m, kW, kH);
  int above = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const glm::dvec3 c = r.at(x, y);
      for (int k = 0; k < 3; ++k) {
        ASSERT_TRUE(std::isfinite(c[k]));
        ASSERT_GE(c[k], 0.0);
      }
      const glm::dvec3 ray = glm::normalize(pixelRay(m, x, y, kW, kH));
      if (ray.z < -0.05) {
        EXPECT_EQ(y709(c), 0.0);
      }
      if (ray.z > 0.3) {
        EXPECT_GT(y709(c), 5e-5);  // airglow + zodiacal light + starlight: ~1e-4 and up
        EXPECT_LT(y709(c), 2e-3);
        ++above;
      }
    }
  EXPECT_GT(above, 100);
}
