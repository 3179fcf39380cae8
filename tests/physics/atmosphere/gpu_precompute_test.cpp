// The GPU precomputation passes (render/passes/precompute/precompute_*.comp) run through OpenGL 4.5
// compute shaders on whatever EGL gives (llvmpipe on CI, a GPU elsewhere) and compared with
// the CPU reference path, which runs the same GLSL as C++ in double precision. Skipped when
// no GL 4.5 context can be created. The precompute is render/passes/precompute/atmosphere_gpu_precompute.h.
#include <glad/gl.h>

#include "render/passes/precompute/atmosphere_gpu_precompute.h"
#include "render/gl/gl_context.h"
#include "render/gl/gl_program.h"
#include "render/passes/sky/physical_sky_pass.h"
#include "render/glsl/bindings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "physics/atmosphere/precompute/precompute.h"
#include "shared_models.h"

namespace skyig::atmosphere {
namespace {

// A compute pass from the embedded shaders, assembled as the renderer assembles them.
GLuint computeProgram(const std::string& pass) {
  return render::linkProgram({render::compileShaderStage(GL_COMPUTE_SHADER, "render/passes/precompute/" + pass)}, pass);
}

void setParameters(GLuint program, const AtmosphereParameters& a) {
  skyig::render::setAtmosphereUniforms(program, "atm", a);
}

GLuint texture2D(int w, int h) {
  GLuint t;
  glCreateTextures(GL_TEXTURE_2D, 1, &t);
  glTextureStorage2D(t, 1, GL_RGBA32F, w, h);
  glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

GLuint texture3D(int w, int h, int d) {
  GLuint t;
  glCreateTextures(GL_TEXTURE_3D, 1, &t);
  glTextureStorage3D(t, 1, GL_RGBA32F, w, h, d);
  glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearTexImage(t, 0, GL_RGBA, GL_FLOAT, zero);
  return t;
}

std::vector<float> readBack(GLuint t, std::size_t texels) {
  std::vector<float> v(texels * 4);
  glGetTextureImage(t, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(v.size() * sizeof(float)), v.data());
  return v;
}

void image(GLuint unit, GLuint t, GLenum access) {
  glBindImageTexture(unit, t, 0, GL_TRUE, 0, access, GL_RGBA32F);
}

void dispatch(GLuint program, int w, int h, int d, int localXy, int localZ) {
  glUseProgram(program);
  glDispatchCompute(static_cast<GLuint>((w + localXy - 1) / localXy),
                    static_cast<GLuint>((h + localXy - 1) / localXy),
                    static_cast<GLuint>((d + localZ - 1) / localZ));
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
}

struct Stats {
  double median = 0.0;
  double p99 = 0.0;
};

// Relative differences of the texels above 1e-3 of the table's largest value.
Stats compare(const std::vector<float>& gpu, const std::vector<glm::dvec4>& cpu) {
  double largest = 0.0;
  for (const auto& t : cpu) largest = std::max({largest, t.x, t.y, t.z, t.w});
  std::vector<double> errors;
  for (std::size_t i = 0; i < cpu.size(); ++i) {
    for (int c = 0; c < 4; ++c) {
      const double ref = cpu[i][c];
      if (ref < 1e-3 * largest) continue;
      errors.push_back(std::abs(static_cast<double>(gpu[i * 4 + static_cast<std::size_t>(c)]) / ref - 1.0));
    }
  }
  std::sort(errors.begin(), errors.end());
  if (errors.empty()) return {};
  return {errors[errors.size() / 2], errors[errors.size() * 99 / 100]};
}

// Relative differences of the texels above 1e-3 of the table's largest value.
Stats compare(const std::vector<glm::dvec4>& gpu, const std::vector<glm::dvec4>& cpu) {
  std::vector<float> flat;
  for (const auto& t : gpu) flat.insert(flat.end(), {float(t.x), float(t.y), float(t.z), float(t.w)});
  return compare(flat, cpu);
}

std::unique_ptr<render::GlContext> makeContext() {
  try {
    return render::createHeadlessContext();
  } catch (const render::GlContextError&) {
    return nullptr;
  }
}


TEST(AtmosphereGpu, ComputePassesMatchTheCpuReferenceAndRepeat) {
  const auto gl = makeContext();
  if (!gl) GTEST_SKIP() << "no OpenGL 4.5 context through EGL";
  std::printf("GL_RENDERER: %s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));

  ModelConfig c = testing::oneGroupConfig();
  // SKYIG_ATMOSPHERE_GPU_FULL=small|medium|default: compare at that size instead (the CPU
  // reference then takes minutes unless it is in the cache already).
  if (const char* size = std::getenv("SKYIG_ATMOSPHERE_GPU_FULL")) c.sizes = TableSizes::named(size);
  const AtmosphereModel model = testing::cachedModel(c);  // the CPU reference (float-rounded)
  const GroupTables& cpu = model.tables(0);
  render::AtmosphereGpuPrecompute precompute;
  render::GpuPrecomputeTiming timing;
  render::GpuPrecomputeOptions options;
  options.time_passes = true;
  const AtmosphereModel gpuModel = precompute.compute(c, options, &timing);
  const GroupTables& gpu = gpuModel.tables(0);
  std::printf("GPU precompute, one group: %s\n", render::describe(timing).c_str());

  const Stats t = compare(gpu.transmittance.texels, cpu.transmittance.texels);
  const Stats e = compare(gpu.irradiance.texels, cpu.irradiance.texels);
  const Stats sc = compare(gpu.scattering.texels, cpu.scattering.texels);
  const Stats m = compare(gpu.singleMie.texels, cpu.singleMie.texels);
  std::printf("GPU precompute (%d x %d x %d x %d tables, %d orders, one group of 4 wavelengths) "
              "%.3f s; GPU vs "
              "CPU relative difference median / 99th percentile: T %.2g / %.2g, E %.2g / %.2g, "
              "S %.2g / %.2g, single Mie %.2g / %.2g\n",
              c.sizes.scatteringR, c.sizes.scatteringMu, c.sizes.scatteringMuS,
              c.sizes.scatteringNu, c.options.scatteringOrders, timing.total, t.median, t.p99, e.median, e.p99,
              sc.median, sc.p99, m.median, m.p99);
  // Float on the GPU against double on the CPU, through the whole chain of orders (measured
  // on llvmpipe, 99th percentiles: small tables 1e-4 to 6e-4, default tables up to 3.1e-3
  // for the single Mie table).
  EXPECT_LT(t.p99, 1e-3);
  EXPECT_LT(sc.median, 1e-4);
  EXPECT_LT(sc.p99, 3e-3);
  EXPECT_LT(m.p99, 5e-3);
  EXPECT_LT(e.p99, 1e-3);

  // Two precomputations with the same parameters give identical tables (the second without
  // per-pass timing, as in production).
  options.time_passes = false;
  const std::vector<GroupTables> again = precompute.computeTables(c, options);
  EXPECT_TRUE(again[0].transmittance.texels == gpu.transmittance.texels);
  EXPECT_TRUE(again[0].irradiance.texels == gpu.irradiance.texels);
  EXPECT_TRUE(again[0].scattering.texels == gpu.scattering.texels);
  EXPECT_TRUE(again[0].singleMie.texels == gpu.singleMie.texels);
}

// Several groups in one call: each group's tables are those of a call with that group alone
// (the textures are reused between groups; nothing of one group may leak into the next).
TEST(AtmosphereGpu, GroupsAreIndependentOfEachOther) {
  const auto gl = makeContext();
  if (!gl) GTEST_SKIP() << "no OpenGL 4.5 context through EGL";
  ModelConfig two = testing::smallEarthConfig();
  two.sizes = testing::tinySizes();
  two.wavelengthsNm = {360.0, 390.0, 420.0, 440.0, 600.0, 630.0, 655.0, 680.0};
  ModelConfig second = two;
  second.wavelengthsNm = {600.0, 630.0, 655.0, 680.0};
  render::AtmosphereGpuPrecompute precompute;
  const std::vector<GroupTables> both = precompute.computeTables(two);
  const std::vector<GroupTables> alone = precompute.computeTables(second);
  ASSERT_EQ(both.size(), 2u);
  EXPECT_TRUE(both[1].scattering.texels == alone[0].scattering.texels);
  EXPECT_TRUE(both[1].irradiance.texels == alone[0].irradiance.texels);
  EXPECT_FALSE(both[0].scattering.texels == both[1].scattering.texels);
}

TEST(AtmosphereGpu, BadOptionsAreRejectedWithTheirName) {
  const auto gl = makeContext();
  if (!gl) GTEST_SKIP() << "no OpenGL 4.5 context through EGL";
  ModelConfig c = testing::oneGroupConfig();
  c.sizes = testing::tinySizes();
  render::AtmosphereGpuPrecompute precompute;
  render::GpuPrecomputeOptions options;
  options.density_divisor = 3;
  try {
    precompute.computeTables(c, options);
    FAIL() << "density_divisor 3 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("density_divisor = 3"), std::string::npos) << e.what();
  }
  c.options.scatteringOrders = 0;
  EXPECT_THROW(precompute.computeTables(c), std::invalid_argument);
}

GLuint upload2D(const shader::cpu_texture::sampler2D& t) {
  const GLuint tex = texture2D(t.width, t.height);
  std::vector<float> data;
  for (const auto& v : t.texels) data.insert(data.end(), {float(v.x), float(v.y), float(v.z), float(v.w)});
  glTextureSubImage2D(tex, 0, 0, 0, t.width, t.height, GL_RGBA, GL_FLOAT, data.data());
  return tex;
}

GLuint upload3D(const shader::cpu_texture::sampler3D& t) {
  const GLuint tex = texture3D(t.width, t.height, t.depth);
  std::vector<float> data;
  for (const auto& v : t.texels) data.insert(data.end(), {float(v.x), float(v.y), float(v.z), float(v.w)});
  glTextureSubImage3D(tex, 0, 0, 0, 0, t.width, t.height, t.depth, GL_RGBA, GL_FLOAT, data.data());
  return tex;
}

TEST(AtmosphereGpu, SkyPanoramaIsFiniteAndMatchesTheCpu) {
  const auto gl = makeContext();
  if (!gl) GTEST_SKIP() << "no OpenGL 4.5 context through EGL";
  const AtmosphereModel model = testing::cachedModel(testing::oneGroupConfig());
  const AtmosphereParameters& atm = model.parameters(0);
  const GroupTables& t = model.tables(0);
  const Medium& m = model.config().medium;
  glBindTextureUnit(SKYIG_UNIT_TRANSMITTANCE, upload2D(t.transmittance));
  glBindTextureUnit(SKYIG_UNIT_SCATTERING, upload3D(t.scattering));
  glBindTextureUnit(SKYIG_UNIT_SINGLE_MIE, upload3D(t.singleMie));
  glBindTextureUnit(SKYIG_UNIT_IRRADIANCE, upload2D(t.irradiance));
  const GLuint program = computeProgram("sky_view.comp");
  setParameters(program, atm);
  const int width = 1920;
  const int height = 1200;
  const GLuint out = texture2D(width, height);
  image(SKYIG_IMAGE_SKY_VIEW, out, GL_WRITE_ONLY);

  struct Case {
    double altitude, sunZenithDeg;
  };
  for (const Case& k : {Case{1000.0, 30.0}, Case{0.0, 90.0}, Case{100e3, 95.0}, Case{1000.0, 108.0}}) {
    const glm::dvec3 camera = observerPosition(m, k.altitude);
    const glm::dvec3 sun = directionFromAngles(k.sunZenithDeg * kDegree, 0.0);
    glUseProgram(program);
    glUniform3f(glGetUniformLocation(program, "camera"), float(camera.x), float(camera.y), float(camera.z));
    glUniform3f(glGetUniformLocation(program, "sun_direction"), float(sun.x), float(sun.y), float(sun.z));
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    dispatch(program, width, height, 1, 8, 1);
    glFinish();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::vector<float> pixels = readBack(out, static_cast<std::size_t>(width) * height);
    int bad = 0;
    for (float v : pixels) bad += (std::isfinite(v) && v >= 0.0f) ? 0 : 1;
    EXPECT_EQ(bad, 0) << "altitude " << k.altitude << " sun zenith " << k.sunZenithDeg;
    std::printf("sky panorama %dx%d, altitude %.0f m, sun zenith %.0f deg: %.1f ms (%.0f ns per "
                "pixel for 4 wavelengths), %d NaN/Inf/negative values\n",
                width, height, k.altitude, k.sunZenithDeg, seconds * 1e3,
                seconds * 1e9 / (width * height), bad);
    // A few pixels against the CPU (double) evaluation of the same functions.
    for (int y : {100, 500, 700, 1100}) {
      for (int x : {0, 480, 960}) {
        const double azimuth = (x + 0.5) / width * 2.0 * kPi;
        const double zenith = (y + 0.5) / height * kPi;
        const glm::dvec3 view = directionFromAngles(zenith, azimuth);
        Spectrum expected = model.skyRadiance(camera, view, sun);
        const Spectrum disc = model.sunDiscRadiance(camera, view, sun);
        const double r = glm::length(camera);
        const double rmu = glm::dot(camera, view);
        const double discGround = rmu * rmu - r * r + m.bottomRadiusM * m.bottomRadiusM;
        Spectrum ground(4, 0.0);
        if (rmu < 0.0 && discGround >= 0.0) {
          const glm::dvec3 point = camera + view * (-rmu - std::sqrt(discGround));
          Spectrum tr;
          const Spectrum total = model.groundRadiance(camera, point, sun, &tr);
          const Spectrum in = model.skyRadianceToPoint(camera, point, sun);
          for (std::size_t i = 0; i < 4; ++i) ground[i] = total[i] - in[i];
        }
        for (std::size_t i = 0; i < 4; ++i) {
          const double e = expected[i] + disc[i] + ground[i];
          const double g = pixels[(static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x)) * 4 + i];
          EXPECT_NEAR(g, e, 2e-3 * e + 1e-9) << "pixel " << x << "," << y << " band " << i
                                             << " altitude " << k.altitude << " sun " << k.sunZenithDeg;
        }
      }
    }
  }
}

}  // namespace
}  // namespace skyig::atmosphere
