// Aerial perspective in a host's own shader (skyig::SkyDraw::aerialPerspectiveGlsl and
// bindAerialPerspective, docs/library.md) against the CPU's (skyig::Sky::aerialPerspective): a
// host program pasted together from its own lines and skyig's GLSL, drawn headless.
#include <skyig/gl_sky.h>
#include <skyig/sky.h>

#include "examples/terrain_host/terrain_host.h"
#include "tests/library/library_test_support.h"
#include "physics/common/units.h"

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

namespace {

using skyig::kDeg;

using skyig::testing::smallPhysicalSky;

skyig::Observer at(int hour, int minute, double heightM) { return skyig::testing::innsbruckAt(hour, minute, heightM); }

GLuint compile(GLenum stage, const std::string& text) {
  const GLuint s = glCreateShader(stage);
  const char* p = text.c_str();
  glShaderSource(s, 1, &p, nullptr);
  glCompileShader(s);
  GLint ok = GL_FALSE;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    std::array<char, 8192> log{};
    glGetShaderInfoLog(s, static_cast<GLsizei>(log.size()), nullptr, log.data());
    ADD_FAILURE() << "the host's shader does not compile: " << log.data();
  }
  return s;
}

// The host's program: a full-screen triangle whose fragment x looks up its point and writes
// skyigAerialPerspective's in-scattered radiance to output 0 and the transmittance to output 1.
// The host has names of its own that skyig's files use too: the pasted text must not meet them.
constexpr int kMaxPoints = 64;
GLuint hostProgram() {
  const std::string vertex = R"(#version 450 core
void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";
  const std::string hostNames = R"(
#define Float double
struct AtmosphereParameters { float bottom_radius; };
float rayleighPhaseFunction(float nu) { return nu; }
)";
  const std::string fragment = "#version 450 core\n" + hostNames + skyig::SkyDraw::aerialPerspectiveGlsl() +
                               "uniform vec3 offsets[" + std::to_string(kMaxPoints) + "];\n" + R"(
layout(location = 0) out vec4 inScattered;
layout(location = 1) out vec4 transmittanceOut;
void main() {
  vec3 transmittance;
  inScattered = vec4(skyigAerialPerspective(offsets[int(gl_FragCoord.x)], transmittance), 1.0);
  transmittanceOut = vec4(transmittance, 1.0);
}
)";
  const GLuint program = glCreateProgram();
  const GLuint v = compile(GL_VERTEX_SHADER, vertex), f = compile(GL_FRAGMENT_SHADER, fragment);
  glAttachShader(program, v);
  glAttachShader(program, f);
  glLinkProgram(program);
  glDeleteShader(v);
  glDeleteShader(f);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  EXPECT_EQ(ok, GL_TRUE);
  return program;
}

struct Gpu {
  std::vector<double> inScattered, transmittance;  // RGBA per point
};

// Draws the points with `program` into a row of float pixels and reads them back.
Gpu drawPoints(GLuint program, const std::vector<skyig::Vec3>& offsets) {
  const int n = static_cast<int>(offsets.size());
  std::vector<float> flat;
  for (const skyig::Vec3& o : offsets)
    for (double c : o) flat.push_back(static_cast<float>(c));
  glProgramUniform3fv(program, glGetUniformLocation(program, "offsets"), n, flat.data());
  GLuint textures[2] = {0, 0}, framebuffer = 0, vao = 0;
  glCreateTextures(GL_TEXTURE_2D, 2, textures);
  glCreateFramebuffers(1, &framebuffer);
  for (int i = 0; i < 2; ++i) {
    glTextureStorage2D(textures[i], 1, GL_RGBA32F, n, 1);
    glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0 + i, textures[i], 0);
  }
  const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(framebuffer, 2, buffers);
  glCreateVertexArrays(1, &vao);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, n, 1);
  glUseProgram(program);
  glBindVertexArray(vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  std::vector<float> pixels(static_cast<std::size_t>(4 * n));
  auto read = [&](GLuint texture) {
    glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(pixels.size() * sizeof(float)), pixels.data());
    return std::vector<double>(pixels.begin(), pixels.end());
  };
  Gpu out{read(textures[0]), read(textures[1])};
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glUseProgram(0);
  glBindVertexArray(0);
  glDeleteVertexArrays(1, &vao);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteTextures(2, textures);
  return out;
}

skyig::Vec3 enu(double azimuthDeg, double elevationDeg, double distanceM) {
  const double a = azimuthDeg * kDeg, e = elevationDeg * kDeg;
  return {distanceM * std::cos(e) * std::sin(a), distanceM * std::cos(e) * std::cos(a), distanceM * std::sin(e)};
}

}  // namespace

// The GLSL a host pastes into its own shader gives the CPU's aerial perspective: in the
// afternoon, at a sunset and at night (the sun 19 deg down, a crescent moon up), from 300 m
// above the ground, for points 100 m to 100 km away level towards and away from the sun (the
// moon at night), level across, and 5 deg down across (the ground is 3.4 km away: the farther
// points lie under it, where both clamp to the ground). The transmittance per Rec.709 channel
// within 1e-3 (the same spectral tables and weights; measured 1.3e-4). The in-scattered
// radiance by day within 7% of its brightest channel and in luminance (measured 5.6% and 5.5%,
// towards the setting sun at 1 km), at night within 15% and 20% (measured 10% and 17%, across,
// towards the deep twilight's glow, at 100 m): the GPU's scattering tables are the CPU's folded
// into Rec.709, so the light scattered beyond the point is attenuated by sunlight's
// transmittance per channel where the CPU attenuates each wavelength by its own, which is the
// further off the less that light's spectrum is the sun's.
TEST(SkyLibrary, GlslAerialPerspectiveIsTheCpus) {
  skyig::Sky sky(smallPhysicalSky());
  terrain_host::HeadlessContext context;
  ASSERT_TRUE(gladLoadGL(reinterpret_cast<GLADloadfunc>(terrain_host::HeadlessContext::procAddress())));
  skyig::SkyDraw draw(terrain_host::HeadlessContext::procAddress());
  const GLuint program = hostProgram();
  ASSERT_NE(program, 0u);

  // Worst differences: of the transmittance; of the in-scatter relative to its brightest channel,
  // and of its luminance; by day and sunset [0] and at night [1].
  double worstT = 0.0, worstS[2] = {0.0, 0.0}, worstY[2] = {0.0, 0.0};
  std::string worstTAt, worstSAt[2], worstYAt[2];
  auto luminance = [](double r, double g, double b) { return 0.2126729 * r + 0.7151522 * g + 0.0721750 * b; };
  for (const auto& [hour, minute] : {std::pair{18, 50}, std::pair{15, 0}, std::pair{21, 30}}) {
    sky.update(at(hour, minute, 300.0), 0.0);
    const int night = hour == 21 ? 1 : 0;
    // The sun's azimuth, or at night (21:30, the sun 19 deg down, a crescent moon 14 deg up
    // lighting the sky) the moon's.
    const skyig::Light light = sky.light();
    const skyig::Vec3 sun = light.sun.direction[2] > -0.1 ? light.sun.direction : light.moon.direction;
    const double sunAzimuthDeg = std::atan2(sun[0], sun[1]) / kDeg;
    struct Ray {
      const char* name;
      double azimuthDeg, elevationDeg;
    };
    const Ray rays[] = {{"towards the light", sunAzimuthDeg, 0.0},
                        {"away from the light", sunAzimuthDeg + 180.0, 0.0},
                        {"across", sunAzimuthDeg + 90.0, 0.0},
                        {"5 deg down across", sunAzimuthDeg + 90.0, -5.0}};
    std::vector<skyig::Vec3> offsets;
    std::vector<std::string> names;
    for (const Ray& r : rays)
      for (double d : {100.0, 1000.0, 10000.0, 100000.0}) {
        offsets.push_back(enu(r.azimuthDeg, r.elevationDeg, d));
        names.push_back(std::to_string(hour) + ":" + std::to_string(minute) + " " + r.name + " at " +
                        std::to_string(static_cast<int>(d)) + " m");
      }
    // Before any SkyDraw::draw: the bind uploads the tables itself, leaving the host's state.
    glUseProgram(0);
    glActiveTexture(GL_TEXTURE3);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
    draw.bindAerialPerspective(sky, program, 4);
    GLint current = -1, active = 0, alignment = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    EXPECT_EQ(current, 0);
    EXPECT_EQ(active, GL_TEXTURE3);
    EXPECT_EQ(alignment, 8);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);

    const Gpu gpu = drawPoints(program, offsets);
    for (std::size_t i = 0; i < offsets.size(); ++i) {
      const skyig::AerialPerspective cpu = sky.aerialPerspective(offsets[i]);
      const double cpuMax = std::max({cpu.inScattered[0], cpu.inScattered[1], cpu.inScattered[2]});
      std::printf("%-40s T %.4f %.4f %.4f (cpu %.4f %.4f %.4f)  S %.4g %.4g %.4g (cpu %.4g %.4g %.4g)\n",
                  names[i].c_str(), gpu.transmittance[4 * i], gpu.transmittance[4 * i + 1], gpu.transmittance[4 * i + 2],
                  cpu.transmittance[0], cpu.transmittance[1], cpu.transmittance[2], gpu.inScattered[4 * i],
                  gpu.inScattered[4 * i + 1], gpu.inScattered[4 * i + 2], cpu.inScattered[0], cpu.inScattered[1],
                  cpu.inScattered[2]);
      const double cpuY = luminance(cpu.inScattered[0], cpu.inScattered[1], cpu.inScattered[2]);
      const double gpuY = luminance(gpu.inScattered[4 * i], gpu.inScattered[4 * i + 1], gpu.inScattered[4 * i + 2]);
      if (std::abs(gpuY - cpuY) / cpuY > worstY[night]) worstY[night] = std::abs(gpuY - cpuY) / cpuY, worstYAt[night] = names[i];
      for (std::size_t c = 0; c < 3; ++c) {
        const double t = std::abs(gpu.transmittance[4 * i + c] - cpu.transmittance[c]);
        // Relative to the brightest channel: a faint channel's small figure is not blown up.
        const double s = std::abs(gpu.inScattered[4 * i + c] - cpu.inScattered[c]) / cpuMax;
        if (t > worstT) worstT = t, worstTAt = names[i];
        if (s > worstS[night]) worstS[night] = s, worstSAt[night] = names[i];
      }
    }
  }
  std::printf("worst: transmittance %.2g (%s)\n", worstT, worstTAt.c_str());
  for (int n = 0; n < 2; ++n)
    std::printf("worst %s: in-scattered %.2f%% of the brightest channel (%s), luminance %.2f%% (%s)\n",
                n ? "at night" : "by day", 100.0 * worstS[n], worstSAt[n].c_str(), 100.0 * worstY[n], worstYAt[n].c_str());
  EXPECT_LT(worstT, 1e-3);
  EXPECT_LT(worstS[0], 0.07);
  EXPECT_LT(worstY[0], 0.07);
  EXPECT_LT(worstS[1], 0.15);
  EXPECT_LT(worstY[1], 0.20);

  EXPECT_THROW(draw.bindAerialPerspective(sky, 0, 4), skyig::Error);
  GLint units = 0;
  glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &units);
  EXPECT_THROW(draw.bindAerialPerspective(sky, program, units - 5), skyig::Error);
  glDeleteProgram(program);
}

// In a 400 m fog (the library's weather: the tables at 10 km and the rest a layer of droplets),
// the GLSL a host pastes keeps Koschmieder's contrast as the CPU does: a black target 400 m off,
// level, against the horizon 20 km off, 0.02 within 20%; and its figures are the CPU's within 1%
// of the light along views through the fog, level and 5 deg down.
TEST(SkyLibrary, GlslAerialPerspectiveInFogKeepsKoschmiedersContrast) {
  skyig::Sky sky(smallPhysicalSky());
  terrain_host::HeadlessContext context;
  ASSERT_TRUE(gladLoadGL(reinterpret_cast<GLADloadfunc>(terrain_host::HeadlessContext::procAddress())));
  skyig::SkyDraw draw(terrain_host::HeadlessContext::procAddress());
  const GLuint program = hostProgram();
  ASSERT_NE(program, 0u);
  skyig::Weather fog;
  fog.visibilityKm = 0.4;
  sky.update(at(11, 0, 100.0), 1.0, fog);
  draw.bindAerialPerspective(sky, program, 4);
  const std::vector<skyig::Vec3> offsets{enu(0.0, 0.0, 400.0), enu(0.0, 0.0, 20000.0), enu(90.0, -5.0, 300.0),
                                         enu(180.0, 0.0, 1000.0)};
  const Gpu gpu = drawPoints(program, offsets);
  auto y = [](const double* c) { return 0.2126729 * c[0] + 0.7151522 * c[1] + 0.0721750 * c[2]; };
  const double contrast = 1.0 - y(&gpu.inScattered[0]) / y(&gpu.inScattered[4]);
  std::printf("GLSL, fog of 400 m: black target at 400 m %.0f cd/m^2 against the horizon %.0f: contrast %.4f\n",
              y(&gpu.inScattered[0]), y(&gpu.inScattered[4]), contrast);
  EXPECT_NEAR(contrast, 0.02, 0.004);
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    const skyig::AerialPerspective cpu = sky.aerialPerspective(offsets[i]);
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_NEAR(gpu.inScattered[4 * i + c], cpu.inScattered[c], 0.01 * cpu.inScattered[c]) << i << " " << c;
      EXPECT_NEAR(gpu.transmittance[4 * i + c], cpu.transmittance[c], 1e-3 + 0.01 * cpu.transmittance[c]) << i << " " << c;
    }
  }
  glDeleteProgram(program);
}

// Under an analytic sky there are no tables to bind.
TEST(SkyLibrary, GlslAerialPerspectiveNeedsThePhysicalSky) {
  skyig::Settings s = smallPhysicalSky();
  s.model = "preetham";
  skyig::Sky sky(s);
  sky.update(at(11, 0, 300.0), 0.0);
  terrain_host::HeadlessContext context;
  ASSERT_TRUE(gladLoadGL(reinterpret_cast<GLADloadfunc>(terrain_host::HeadlessContext::procAddress())));
  skyig::SkyDraw draw(terrain_host::HeadlessContext::procAddress());
  const GLuint program = hostProgram();
  EXPECT_THROW(draw.bindAerialPerspective(sky, program, 0), skyig::Error);
  glDeleteProgram(program);
}
