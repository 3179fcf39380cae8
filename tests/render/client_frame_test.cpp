// The sky drawn into a client image generator's frame (render/client/client_frame.h), headless: only where
// the client's depth buffer is at the far plane, for both depth conventions; the client's GL state
// left as it was; linear output equal to the sky's radiance; the camera read back from the
// client's matrices.
#include "render/gl/gl_context.h"
#include "render/gl/gl_program.h"
#include "render/gl/gl_state_guard.h"
#include "render/client/client_frame.h"
#include "render/sky_renderer.h"
#include "physics/common/units.h"
#include "tests/physics/atmosphere/shared_models.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace skyig;
using namespace skyig::render;
using namespace skyig::sky;

namespace {

using skyig::kDeg;
constexpr int kW = 128, kH = 96;

// The GL view matrix of a skyig eye (ownship attitude and channel offset) at `position` (ENU
// metres): the inverse of eye -> world, with GL's eye axes (x right, y up, z backwards) made
// from skyig's (x forward, y right, z down).
glm::dmat4 viewOf(const Attitude& ownship, const Attitude& offset, glm::dvec3 position = {120.0, -40.0, 1500.0}) {
  const glm::dmat3 m = eyeToEnu(ownship, offset);
  const glm::dmat3 glEyeToEnu(m[1], -m[2], -m[0]);
  const glm::dmat3 r = glm::transpose(glEyeToEnu);
  glm::dmat4 view(r);
  view[3] = glm::dvec4(-(r * position), 1.0);
  return view;
}

// glFrustum's matrix for the half-angles at `nearM`/`farM`; reverse-Z: the infinite far plane
// at NDC depth 0 and the near plane at 1 (for GL_ZERO_TO_ONE clip control).
glm::dmat4 projectionOf(const Frustum& f, bool reverseZ, double nearM = 0.5, double farM = 20000.0) {
  const double l = -nearM * std::tan(f.leftDeg * kDeg), r = nearM * std::tan(f.rightDeg * kDeg);
  const double b = -nearM * std::tan(f.downDeg * kDeg), t = nearM * std::tan(f.upDeg * kDeg);
  glm::dmat4 p(0.0);
  p[0][0] = 2.0 * nearM / (r - l);
  p[1][1] = 2.0 * nearM / (t - b);
  p[2][0] = (r + l) / (r - l);
  p[2][1] = (t + b) / (t - b);
  p[2][3] = -1.0;
  if (reverseZ) {
    p[3][2] = nearM;
  } else {
    p[2][2] = -(farM + nearM) / (farM - nearM);
    p[3][2] = -2.0 * farM * nearM / (farM - nearM);
  }
  return p;
}

ChannelConfig channelOf(const Attitude& offset, const Frustum& f) {
  ChannelConfig c;
  c.name = "host";
  c.offset = offset;
  c.frustum = f;
  c.width = kW;
  c.height = kH;
  return c;
}

// A client framebuffer: a colour texture and a 32-bit float depth buffer.
struct HostTarget {
  HostTarget(int width, int height, GLenum colorFormat) : w(width), h(height) {
    glCreateTextures(GL_TEXTURE_2D, 1, &color);
    glTextureStorage2D(color, 1, colorFormat, w, h);
    glCreateRenderbuffers(1, &depth);
    glNamedRenderbufferStorage(depth, GL_DEPTH_COMPONENT32F, w, h);
    glCreateFramebuffers(1, &fbo);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, color, 0);
    glNamedFramebufferRenderbuffer(fbo, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  }
  ~HostTarget() {
    glDeleteFramebuffers(1, &fbo);
    glDeleteRenderbuffers(1, &depth);
    glDeleteTextures(1, &color);
  }
  HostTarget(const HostTarget&) = delete;
  HostTarget& operator=(const HostTarget&) = delete;
  bool complete() const { return glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE; }
  // Bottom row first, as GL stores it.
  std::vector<std::uint8_t> readRgba8() const {
    std::vector<std::uint8_t> p(static_cast<std::size_t>(w * h * 4));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(color, 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(p.size()), p.data());
    return p;
  }
  std::vector<float> readRgba32f() const {
    std::vector<float> p(static_cast<std::size_t>(w * h * 4));
    glGetTextureImage(color, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(p.size() * sizeof(float)), p.data());
    return p;
  }
  std::vector<float> readDepth() const {
    std::vector<float> d(static_cast<std::size_t>(w * h));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, d.data());
    return d;
  }
  int w, h;
  GLuint color = 0, depth = 0, fbo = 0;
};

class HostFrame : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    context_ = createHeadlessContext().release();
    host_ = new ClientFrameRenderer();
  }
  static void TearDownTestSuite() {
    delete host_;
    delete context_;
  }
  // A day sky: the sun at 35 deg in the south-west, the observer heading north-east.
  static SkyState dayState() {
    ObserverState o;
    o.attitude = {40.0, 3.0, -2.0};
    return buildSkyState(o, SkyConditions{}, SunOverride{220.0, 35.0});
  }
  static inline GlContext* context_ = nullptr;
  static inline ClientFrameRenderer* host_ = nullptr;
};

class HostFrameDepth : public HostFrame, public ::testing::WithParamInterface<DepthConvention> {};

}  // namespace

// The client clears to magenta at the far plane and draws its "terrain" (a solid colour at a
// near depth) over the lower half; after the sky's draw the terrain is unchanged pixel for
// pixel, the upper half shows the sky's display frame (no magenta left), and the client's depth
// buffer is as it was.
TEST_P(HostFrameDepth, SkyFillsOnlyWhereTheHostLeftTheFarPlane) {
  const bool reverseZ = GetParam() == DepthConvention::ReverseZ;
  const SkyState s = dayState();
  const Frustum f{30, 30, 22, 22};
  HostTarget target(kW, kH, GL_RGBA8);
  ASSERT_TRUE(target.complete());
  glClipControl(GL_LOWER_LEFT, reverseZ ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
  const float farDepth = reverseZ ? 0.0f : 1.0f, terrainDepth = reverseZ ? 0.7f : 0.3f;
  glBindFramebuffer(GL_FRAMEBUFFER, target.fbo);
  glViewport(0, 0, kW, kH);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClearColor(1.0f, 0.0f, 1.0f, 1.0f);
  glClearDepth(farDepth);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, kW, kH / 2);
  glClearColor(0.2f, 0.6f, 0.1f, 1.0f);
  glClearDepth(terrainDepth);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  const std::vector<std::uint8_t> before = target.readRgba8();

  ClientFrameOptions options;
  options.depth = GetParam();
  host_->draw(s, viewOf(s.observer.attitude, {0.0, 5.0, 0.0}), projectionOf(f, reverseZ), {0, 0, kW, kH}, options);
  glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
  glClearDepth(1.0);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));

  const std::vector<std::uint8_t> after = target.readRgba8();
  const DisplayImage sky = host_->skyRenderer().readDisplay();
  ASSERT_EQ(sky.width, kW);
  ASSERT_EQ(sky.height, kH);
  const std::vector<float> depth = target.readDepth();
  int terrainChanged = 0, skyWrong = 0, magentaLeft = 0, depthChanged = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * kW + x) * 4;
      const std::uint8_t* skyPixel = &sky.rgba[static_cast<std::size_t>((kH - 1 - y) * kW + x) * 4];
      const bool terrain = y < kH / 2;
      for (int c = 0; c < 4; ++c) {
        if (terrain) terrainChanged += after[i + c] != before[i + c];
        else skyWrong += after[i + c] != (c < 3 ? skyPixel[c] : 255);
      }
      if (!terrain) magentaLeft += after[i] == 255 && after[i + 1] == 0 && after[i + 2] == 255;
      depthChanged += depth[i / 4] != (terrain ? terrainDepth : farDepth);
    }
  EXPECT_EQ(terrainChanged, 0) << "terrain channel values the sky overwrote";
  EXPECT_EQ(skyWrong, 0) << "sky channel values that differ from the sky's display frame";
  EXPECT_EQ(magentaLeft, 0) << "far-plane pixels the sky left at the client's clear colour";
  EXPECT_EQ(depthChanged, 0) << "depth values the sky wrote";
  // Not a flat frame: the sky differs from the terrain colour and has a gradient.
  EXPECT_NE(after[static_cast<std::size_t>((kH - 1) * kW) * 4 + 2], before[2]);
}

INSTANTIATE_TEST_SUITE_P(BothConventions, HostFrameDepth,
                         ::testing::Values(DepthConvention::Standard, DepthConvention::ReverseZ),
                         [](const ::testing::TestParamInfo<DepthConvention>& p) {
                           return p.param == DepthConvention::Standard ? std::string("StandardDepth")
                                                                       : std::string("ReverseZ");
                         });

namespace {

// Every piece of state GlStateGuard lists, read independently of it, by name.
std::vector<std::pair<std::string, double>> snapshot() {
  std::vector<std::pair<std::string, double>> s;
  auto integer = [&](const std::string& name, GLenum e) {
    GLint v[4] = {0, 0, 0, 0};
    glGetIntegerv(e, v);
    s.emplace_back(name, v[0]);
  };
  integer("draw framebuffer", GL_DRAW_FRAMEBUFFER_BINDING);
  integer("read framebuffer", GL_READ_FRAMEBUFFER_BINDING);
  integer("program", GL_CURRENT_PROGRAM);
  integer("vertex array", GL_VERTEX_ARRAY_BINDING);
  integer("array buffer", GL_ARRAY_BUFFER_BINDING);
  integer("uniform buffer", GL_UNIFORM_BUFFER_BINDING);
  integer("pixel pack buffer", GL_PIXEL_PACK_BUFFER_BINDING);
  integer("pixel unpack buffer", GL_PIXEL_UNPACK_BUFFER_BINDING);
  integer("active texture", GL_ACTIVE_TEXTURE);
  integer("depth func", GL_DEPTH_FUNC);
  integer("clip origin", GL_CLIP_ORIGIN);
  integer("clip depth mode", GL_CLIP_DEPTH_MODE);
  integer("pack alignment", GL_PACK_ALIGNMENT);
  integer("unpack alignment", GL_UNPACK_ALIGNMENT);
  integer("pack row length", GL_PACK_ROW_LENGTH);
  integer("unpack row length", GL_UNPACK_ROW_LENGTH);
  for (auto [name, e] : {std::pair{"viewport", GL_VIEWPORT}, std::pair{"scissor box", GL_SCISSOR_BOX}}) {
    GLint v[4];
    glGetIntegerv(e, v);
    for (int i = 0; i < 4; ++i) s.emplace_back(std::string(name) + "[" + std::to_string(i) + "]", v[i]);
  }
  for (auto [name, e] : {std::pair{"colour clear", GL_COLOR_CLEAR_VALUE}, std::pair{"blend colour", GL_BLEND_COLOR}}) {
    GLfloat v[4];
    glGetFloatv(e, v);
    for (int i = 0; i < 4; ++i) s.emplace_back(std::string(name) + "[" + std::to_string(i) + "]", v[i]);
  }
  GLboolean depthMask = GL_FALSE;
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
  s.emplace_back("depth mask", depthMask);
  GLdouble depthClear = 0.0;
  glGetDoublev(GL_DEPTH_CLEAR_VALUE, &depthClear);
  s.emplace_back("depth clear", depthClear);
  GLdouble depthRange[2] = {0.0, 0.0};
  glGetDoublev(GL_DEPTH_RANGE, depthRange);
  s.emplace_back("depth range near", depthRange[0]);
  s.emplace_back("depth range far", depthRange[1]);
  for (auto [name, e] : {std::pair{"depth test", GL_DEPTH_TEST}, std::pair{"cull face", GL_CULL_FACE},
                         std::pair{"scissor test", GL_SCISSOR_TEST}, std::pair{"stencil test", GL_STENCIL_TEST},
                         std::pair{"framebuffer sRGB", GL_FRAMEBUFFER_SRGB},
                         std::pair{"rasterizer discard", GL_RASTERIZER_DISCARD},
                         std::pair{"polygon offset fill", GL_POLYGON_OFFSET_FILL},
                         std::pair{"alpha to coverage", GL_SAMPLE_ALPHA_TO_COVERAGE},
                         std::pair{"depth clamp", GL_DEPTH_CLAMP}})
    s.emplace_back(name, glIsEnabled(e));
  GLint drawBuffers = 0;
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &drawBuffers);
  for (GLuint i = 0; i < static_cast<GLuint>(drawBuffers); ++i) {
    const std::string n = "[" + std::to_string(i) + "]";
    s.emplace_back("blend" + n, glIsEnabledi(GL_BLEND, i));
    for (auto [name, e] : {std::pair{"blend src rgb", GL_BLEND_SRC_RGB}, std::pair{"blend dst rgb", GL_BLEND_DST_RGB},
                           std::pair{"blend src alpha", GL_BLEND_SRC_ALPHA},
                           std::pair{"blend dst alpha", GL_BLEND_DST_ALPHA},
                           std::pair{"blend equation rgb", GL_BLEND_EQUATION_RGB},
                           std::pair{"blend equation alpha", GL_BLEND_EQUATION_ALPHA}}) {
      GLint v = 0;
      glGetIntegeri_v(e, i, &v);
      s.emplace_back(name + n, v);
    }
    GLboolean mask[4];
    glGetBooleani_v(GL_COLOR_WRITEMASK, i, mask);
    for (int c = 0; c < 4; ++c) s.emplace_back("colour mask" + n + "[" + std::to_string(c) + "]", mask[c]);
  }
  GLint active = 0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
  for (GLuint unit : GlStateGuard::savedTextureUnits()) {
    glActiveTexture(GL_TEXTURE0 + unit);
    const std::string n = " unit " + std::to_string(unit);
    for (auto [name, e] : {std::pair{"texture 1D", GL_TEXTURE_BINDING_1D}, std::pair{"texture 2D", GL_TEXTURE_BINDING_2D},
                           std::pair{"texture 3D", GL_TEXTURE_BINDING_3D}, std::pair{"sampler", GL_SAMPLER_BINDING}}) {
      GLint v = 0;
      glGetIntegerv(e, &v);
      s.emplace_back(name + n, v);
    }
  }
  glActiveTexture(static_cast<GLenum>(active));
  for (GLuint index : GlStateGuard::savedUniformBindings()) {
    const std::string n = " " + std::to_string(index);
    GLint buffer = 0;
    GLint64 start = 0, size = 0;
    glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, index, &buffer);
    glGetInteger64i_v(GL_UNIFORM_BUFFER_START, index, &start);
    glGetInteger64i_v(GL_UNIFORM_BUFFER_SIZE, index, &size);
    s.emplace_back("uniform binding" + n, buffer);
    s.emplace_back("uniform start" + n, static_cast<double>(start));
    s.emplace_back("uniform size" + n, static_cast<double>(size));
  }
  return s;
}

}  // namespace

// A client with a value other than GL's default in every piece of state the guard lists (and a
// texture, sampler and uniform buffer range on every unit and index the sky uses) finds each
// of them as it left it after a draw.
TEST_F(HostFrame, HostGlStateIsTheSameAfterADraw) {
  const SkyState s = dayState();
  HostTarget target(kW, kH, GL_RGBA8), other(kW, kH, GL_RGBA8);
  const GlProgram hostProgram("render/client/client_frame.vert", "render/client/client_frame.frag");
  GLuint vao = 0, buffers[4] = {}, samplers = 0, t1 = 0, t2 = 0, t3 = 0;
  glCreateVertexArrays(1, &vao);
  glCreateBuffers(4, buffers);
  for (GLuint b : buffers) glNamedBufferData(b, 4096, nullptr, GL_STATIC_DRAW);
  glCreateSamplers(1, &samplers);
  glCreateTextures(GL_TEXTURE_1D, 1, &t1);
  glTextureStorage1D(t1, 1, GL_RGBA8, 4);
  glCreateTextures(GL_TEXTURE_2D, 1, &t2);
  glTextureStorage2D(t2, 1, GL_RGBA8, 4, 4);
  glCreateTextures(GL_TEXTURE_3D, 1, &t3);
  glTextureStorage3D(t3, 1, GL_RGBA8, 4, 4, 4);

  // The client's own frame: its clear colour, the far plane everywhere.
  glBindFramebuffer(GL_FRAMEBUFFER, target.fbo);
  glViewport(0, 0, kW, kH);
  glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  glBindFramebuffer(GL_READ_FRAMEBUFFER, other.fbo);
  hostProgram.use();
  glBindVertexArray(vao);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, buffers[1]);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffers[2]);
  for (GLuint unit : GlStateGuard::savedTextureUnits()) {
    for (GLuint t : {t1, t2, t3}) glBindTextureUnit(unit, t);
    glBindSampler(unit, samplers);
  }
  glActiveTexture(GL_TEXTURE5);
  GLintptr offset = 0;
  for (GLuint index : GlStateGuard::savedUniformBindings())
    glBindBufferRange(GL_UNIFORM_BUFFER, index, buffers[3], offset += 256, 512);
  glBindBuffer(GL_UNIFORM_BUFFER, buffers[1]);
  glViewport(3, 5, 100, 80);
  glScissor(1, 2, 30, 40);
  for (GLenum cap : GlStateGuard::savedCapabilities()) glEnable(cap);
  glEnablei(GL_BLEND, 0);
  glBlendFuncSeparatei(0, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ZERO);
  glBlendEquationSeparatei(0, GL_FUNC_SUBTRACT, GL_MAX);
  glColorMaski(0, GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  glBlendFuncSeparatei(1, GL_DST_COLOR, GL_ONE, GL_SRC_ALPHA, GL_ONE);
  glColorMaski(1, GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_FALSE);
  glClearDepth(0.25);
  glDepthRange(0.2, 0.9);
  glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
  glBlendColor(0.5f, 0.6f, 0.7f, 0.8f);
  glPixelStorei(GL_PACK_ALIGNMENT, 2);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
  glPixelStorei(GL_PACK_ROW_LENGTH, 7);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 9);
  ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));

  const auto before = snapshot();
  host_->draw(s, viewOf(s.observer.attitude, {}), projectionOf(Frustum{30, 30, 22, 22}, false), {0, 0, kW, kH});
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  const auto after = snapshot();
  ASSERT_EQ(before.size(), after.size());
  for (std::size_t i = 0; i < before.size(); ++i) EXPECT_EQ(after[i].second, before[i].second) << before[i].first;

  // Back to GL's defaults for the next test (this suite shares one context), then the sky's draw
  // wrote the client's framebuffer through all of it: no pixel left at the clear colour.
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  for (GLenum cap : GlStateGuard::savedCapabilities()) glDisable(cap);
  glDisable(GL_BLEND);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glBlendFunc(GL_ONE, GL_ZERO);
  glBlendEquation(GL_FUNC_ADD);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glClearDepth(1.0);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glBlendColor(0.0f, 0.0f, 0.0f, 0.0f);
  glDepthRange(0.0, 1.0);
  glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
  for (GLuint unit : GlStateGuard::savedTextureUnits()) {
    glBindTextureUnit(unit, 0);
    glBindSampler(unit, 0);
  }
  glActiveTexture(GL_TEXTURE0);
  glUseProgram(0);
  glBindVertexArray(0);
  const std::vector<std::uint8_t> pixels = target.readRgba8();
  int clearLeft = 0;
  for (std::size_t i = 0; i < pixels.size(); i += 4) clearLeft += pixels[i] == 26 && pixels[i + 1] == 51 && pixels[i + 2] == 77;
  EXPECT_EQ(clearLeft, 0);
  glDeleteTextures(1, &t1);
  glDeleteTextures(1, &t2);
  glDeleteTextures(1, &t3);
  glDeleteSamplers(1, &samplers);
  glDeleteBuffers(4, buffers);
  glDeleteVertexArrays(1, &vao);
}

// Linear output into a float host target, in a viewport away from the target's corner: every
// pixel equals the HDR image (cd/m^2) of the same channel drawn by a SkyRenderer of its own,
// and the pixels outside the viewport keep the client's clear colour.
TEST_F(HostFrame, LinearOutputIsTheSkysRadiance) {
  const SkyState s = dayState();
  const Attitude offset{-20.0, 12.0, 4.0};
  const Frustum f{25, 35, 15, 28};  // off-axis
  const ChannelConfig c = channelOf(offset, f);
  SkyRenderer own;
  own.draw(s, c);
  const HdrImage expected = own.readHdr();

  const int x0 = 16, y0 = 8, w = kW + 32, h = kH + 16;
  HostTarget target(w, h, GL_RGBA32F);
  ASSERT_TRUE(target.complete());
  glBindFramebuffer(GL_FRAMEBUFFER, target.fbo);
  glViewport(0, 0, w, h);
  glClearColor(-1.0f, -2.0f, -3.0f, -4.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  ClientFrameOptions options;
  options.output = ClientOutput::LinearLight;
  options.display = c.display;
  host_->draw(s, viewOf(s.observer.attitude, offset), projectionOf(f, false), {x0, y0, kW, kH}, options);
  ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));

  const std::vector<float> got = target.readRgba32f();
  int outside = 0, differ = 0;
  double worst = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float* p = &got[static_cast<std::size_t>(y * w + x) * 4];
      const bool inside = x >= x0 && x < x0 + kW && y >= y0 && y < y0 + kH;
      if (!inside) {
        outside += p[0] != -1.0f || p[1] != -2.0f || p[2] != -3.0f || p[3] != -4.0f;
        continue;
      }
      const float* e = expected.pixel(x - x0, kH - 1 - (y - y0));  // image rows start at the top
      for (int k = 0; k < 3; ++k) {
        const double rel = std::abs(static_cast<double>(p[k]) - static_cast<double>(e[k])) / std::max(std::abs(static_cast<double>(e[k])), 1e-6);
        worst = std::max(worst, rel);
        differ += rel > 1e-4;
      }
      differ += p[3] != 1.0f;
    }
  EXPECT_EQ(outside, 0) << "pixels outside the viewport that changed";
  EXPECT_EQ(differ, 0) << "values off the channel's radiance; worst relative difference " << worst;
  // Daylight: thousands of cd/m^2, not display values.
  EXPECT_GT(got[static_cast<std::size_t>(((y0 + kH / 2) * w + x0 + kW / 2) * 4 + 2)], 500.0f);
}

// A view and projection built from known channels (ownship attitude, eyepoint offset,
// asymmetric frustum; straight up; standard and reverse-Z projections, a view with a
// translation and a uniform scale) give back the same frustum and the same view rays.
TEST_F(HostFrame, CameraFromMatricesMatchesTheChannel) {
  struct Case {
    Attitude ownship, offset;
    Frustum frustum;
    bool reverseZ;
    double viewScale;
  };
  const Case cases[] = {
      {{30.0, 5.0, -10.0}, {45.0, 10.0, 0.0}, {20.0, 35.0, 10.0, 25.0}, false, 1.0},
      {{-170.0, -20.0, 60.0}, {0.0, 0.0, 0.0}, {40.0, 40.0, 30.0, 30.0}, true, 1.0},
      {{10.0, 90.0, 0.0}, {0.0, 0.0, 0.0}, {30.0, 30.0, 30.0, 30.0}, false, 2.5},   // straight up
      {{200.0, 0.0, 0.0}, {0.0, -90.0, 0.0}, {10.0, 60.0, 5.0, 45.0}, true, 1.0},   // straight down
      {{0.0, 0.0, 0.0}, {-60.0, 0.0, 15.0}, {-10.0, 40.0, 20.0, 20.0}, false, 1.0}, // forward off the frustum
  };
  for (const Case& k : cases) {
    SCOPED_TRACE("ownship yaw " + std::to_string(k.ownship.yawDeg) + " pitch " + std::to_string(k.ownship.pitchDeg) +
                 ", offset yaw " + std::to_string(k.offset.yawDeg) + " pitch " + std::to_string(k.offset.pitchDeg));
    glm::dmat4 view = viewOf(k.ownship, k.offset);
    view = glm::dmat4(glm::dmat3(view) * k.viewScale);
    view[3] = glm::dvec4(10.0, 20.0, -30.0, 1.0);
    const ClientCamera camera = clientCamera(view, projectionOf(k.frustum, k.reverseZ) * 3.0);
    EXPECT_NEAR(camera.frustum.leftDeg, k.frustum.leftDeg, 1e-9);
    EXPECT_NEAR(camera.frustum.rightDeg, k.frustum.rightDeg, 1e-9);
    EXPECT_NEAR(camera.frustum.downDeg, k.frustum.downDeg, 1e-9);
    EXPECT_NEAR(camera.frustum.upDeg, k.frustum.upDeg, 1e-9);
    const glm::dmat3 want = ndcToWorld(eyeToEnu(k.ownship, k.offset), k.frustum);
    const glm::dmat3 got = ndcToWorld(eyeToEnu(camera.attitude, {}), camera.frustum);
    for (int col = 0; col < 3; ++col)
      for (int row = 0; row < 3; ++row) EXPECT_NEAR(got[col][row], want[col][row], 1e-9) << col << "," << row;
  }
  // No sky frustum: an orthographic projection, a mirrored view.
  glm::dmat4 ortho(1.0);
  ortho[3][2] = -0.5;
  EXPECT_THROW(clientCamera(glm::dmat4(1.0), ortho), std::invalid_argument);
  glm::dmat4 mirrored = viewOf({}, {});
  mirrored[0] = -mirrored[0];
  EXPECT_THROW(clientCamera(mirrored, projectionOf(Frustum{}, false)), std::invalid_argument);
}

namespace {

// Innsbruck on midsummer's day (the observer's default) under the physical sky's tiny tables,
// at `utcHour`, clear or under a ground fog of 300 m visibility 150 m deep, mapped for the
// client's display as the library maps its states.
SkyState innsbruckAt(double utcHour, bool fog) {
  SkyConditions c;
  c.model = SkyModel::Physical;
  c.atmosphere = atmosphere::testing::tinyNightModel();
  if (fog) c.fog = FogSpec{0.0, 150.0, 0.3};
  ObserverState o;
  o.attitude = {250.0, 5.0, 0.0};
  o.utc.secondsOfDay = 3600.0 * utcHour;
  SkyState s = buildSkyState(o, c);
  mapForDisplays(s, {ClientFrameOptions{}.display});
  return s;
}

}  // namespace

// A client that prepared its first state's day (ClientFrameRenderer::prepare) flies through that
// day's morning, noon, dusk and night, clear and in fog, without linking one program more; one
// that did not links programs at its first dusk (each a second on llvmpipe: a frame lost).
TEST(ClientFramePrepare, APreparedDayCompilesNothingMidFrame) {
  const auto context = createHeadlessContext();
  const Frustum f{30, 30, 20, 20};
  const glm::dmat4 view = viewOf({250.0, 5.0, 0.0}, {}), projection = projectionOf(f, false);
  const ClientViewport viewport{0, 0, kW, kH};
  const SkyState first = innsbruckAt(9.0, false);

  ClientFrameRenderer unprepared;
  unprepared.drawTexture(first, view, projection, kW, kH);
  const std::size_t beforeDusk = programsLinked();
  unprepared.drawTexture(innsbruckAt(20.25, false), view, projection, kW, kH);
  EXPECT_GT(programsLinked(), beforeDusk) << "dusk needs programs a morning does not: the check below could not fail";

  ClientFrameRenderer prepared;
  prepared.prepare(first, view, projection, viewport);
  const std::size_t afterPrepare = programsLinked();
  for (const double hour : {9.0, 11.5, 15.0, 18.5, 19.5, 20.25, 21.0, 22.0, 23.5, 1.0, 2.5, 3.5})
    for (const bool fog : {false, true}) {
      const SkyState s = innsbruckAt(hour, fog);
      prepared.drawTexture(s, view, projection, kW, kH);
      EXPECT_EQ(programsLinked(), afterPrepare)
          << hour << " h UTC" << (fog ? " in fog" : "") << ", sun at " << s.sunAltitude / kDeg << " deg";
    }
}
