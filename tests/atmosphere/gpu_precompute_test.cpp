// The GPU precomputation passes (shaders/atmosphere/precompute_*.comp) run through OpenGL 4.5
// compute shaders on whatever EGL gives (llvmpipe on CI, a GPU elsewhere) and compared with
// the CPU reference path, which runs the same GLSL as C++ in double precision. Skipped when
// no GL 4.5 context can be created. This test has its own minimal EGL context and shader
// assembly; the renderer's own GL context and loader (render/) will drive the same passes.
#include <glad/gl.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include "render/physical_sky_pass.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "render/atmosphere/precompute.h"
#include "shared_models.h"

namespace skyig::atmosphere {
namespace {

std::string readShader(const std::string& name) {
  std::ifstream f(std::string(SKYIG_SOURCE_DIR) + "/shaders/" + name);
  if (!f) throw std::runtime_error("cannot read shader " + name);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// Inlines `#include "x"` relative to shaders/ (include guards handle repeats).
std::string resolveIncludes(const std::string& text, int depth = 0) {
  if (depth > 16) throw std::runtime_error("include depth");
  std::istringstream in(text);
  std::string line;
  std::string out;
  while (std::getline(in, line)) {
    const auto p = line.find("#include \"");
    if (p != std::string::npos && line.find_first_not_of(" \t") == p) {
      const auto q = line.find('"', p + 10);
      out += resolveIncludes(readShader(line.substr(p + 10, q - p - 10)), depth + 1);
    } else {
      out += line + "\n";
    }
  }
  return out;
}

class GlContext {
 public:
  bool create() {
    auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_platform_display) return false;
    display_ = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, nullptr, nullptr)) return false;
    if (!eglBindAPI(EGL_OPENGL_API)) return false;
    const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    // Surfaceless Mesa may list no config: EGL_KHR_no_config_context then takes none.
    if (!eglChooseConfig(display_, config_attribs, &config, 1, &count) || count < 1) {
      config = nullptr;
    }
    const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, context_attribs);
    if (context_ == EGL_NO_CONTEXT) return false;
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) return false;
    return gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress)) != 0;
  }
  ~GlContext() {
    if (context_ != EGL_NO_CONTEXT) {
      eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      eglDestroyContext(display_, context_);
    }
    if (display_ != EGL_NO_DISPLAY) eglTerminate(display_);
  }

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

GLuint computeProgram(const std::string& pass) {
  const std::string source = "#version 450 core\n" +
                             resolveIncludes(readShader("common/glsl_prelude.glsl")) +
                             resolveIncludes(readShader("atmosphere/" + pass));
  const char* text = source.c_str();
  const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    throw std::runtime_error(pass + ": " + log);
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  glLinkProgram(program);
  glDeleteShader(shader);
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) throw std::runtime_error(pass + ": link failed");
  return program;
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

void dispatch(GLuint program, int w, int h, int d, int local_xy, int local_z) {
  glUseProgram(program);
  glDispatchCompute(static_cast<GLuint>((w + local_xy - 1) / local_xy),
                    static_cast<GLuint>((h + local_xy - 1) / local_xy),
                    static_cast<GLuint>((d + local_z - 1) / local_z));
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

struct GpuTables {
  std::vector<float> transmittance, irradiance, scattering, single_mie;
  double seconds = 0.0;
};

// Runs the passes in the order of render/atmosphere/precompute.cpp and reads the tables back.
GpuTables runGpuPrecompute(const AtmosphereParameters& atm, const TableSizes& s, int orders) {
  const int sw = s.scattering_nu * s.scattering_mu_s;
  const int sh = s.scattering_mu;
  const int sd = s.scattering_r;

  const GLuint p_transmittance = computeProgram("precompute_transmittance.comp");
  const GLuint p_direct = computeProgram("precompute_direct_irradiance.comp");
  const GLuint p_single = computeProgram("precompute_single_scattering.comp");
  const GLuint p_density = computeProgram("precompute_scattering_density.comp");
  const GLuint p_indirect = computeProgram("precompute_indirect_irradiance.comp");
  const GLuint p_multiple = computeProgram("precompute_multiple_scattering.comp");
  const GLuint programs[] = {p_transmittance, p_direct, p_single, p_density, p_indirect, p_multiple};
  for (GLuint p : programs) setParameters(p, atm);

  const GLuint transmittance = texture2D(s.transmittance_mu, s.transmittance_r);
  const GLuint delta_irradiance = texture2D(s.irradiance_mu_s, s.irradiance_r);
  const GLuint irradiance = texture2D(s.irradiance_mu_s, s.irradiance_r);
  const GLuint delta_rayleigh = texture3D(sw, sh, sd);
  const GLuint delta_mie = texture3D(sw, sh, sd);
  const GLuint scattering = texture3D(sw, sh, sd);
  const GLuint single_mie = texture3D(sw, sh, sd);
  const GLuint delta_multiple = texture3D(sw, sh, sd);
  const GLuint delta_density = texture3D(sw, sh, sd);

  const auto start = std::chrono::steady_clock::now();
  image(0, transmittance, GL_WRITE_ONLY);
  dispatch(p_transmittance, s.transmittance_mu, s.transmittance_r, 1, 8, 1);
  glBindTextureUnit(0, transmittance);
  image(0, delta_irradiance, GL_WRITE_ONLY);
  image(1, irradiance, GL_WRITE_ONLY);
  dispatch(p_direct, s.irradiance_mu_s, s.irradiance_r, 1, 8, 1);
  image(0, delta_rayleigh, GL_WRITE_ONLY);
  image(1, delta_mie, GL_WRITE_ONLY);
  image(2, scattering, GL_WRITE_ONLY);
  image(3, single_mie, GL_WRITE_ONLY);
  dispatch(p_single, sw, sh, sd, 4, 4);
  for (int order = 2; order <= orders; ++order) {
    glBindTextureUnit(1, delta_rayleigh);
    glBindTextureUnit(2, delta_mie);
    glBindTextureUnit(3, delta_multiple);
    glBindTextureUnit(4, delta_irradiance);
    image(0, delta_density, GL_WRITE_ONLY);
    glUseProgram(p_density);
    glUniform1i(glGetUniformLocation(p_density, "scattering_order"), order);
    dispatch(p_density, sw, sh, sd, 4, 4);
    // delta_irradiance and delta_multiple are rewritten next: unbind them as samplers.
    glBindTextureUnit(4, 0);
    image(0, delta_irradiance, GL_WRITE_ONLY);
    image(1, irradiance, GL_READ_WRITE);
    glUseProgram(p_indirect);
    glUniform1i(glGetUniformLocation(p_indirect, "scattering_order"), order);
    dispatch(p_indirect, s.irradiance_mu_s, s.irradiance_r, 1, 8, 1);
    glBindTextureUnit(3, 0);
    glBindTextureUnit(5, delta_density);
    image(0, delta_multiple, GL_WRITE_ONLY);
    image(2, scattering, GL_READ_WRITE);
    dispatch(p_multiple, sw, sh, sd, 4, 4);
  }
  glFinish();
  GpuTables out;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  const auto t2 = static_cast<std::size_t>(s.transmittance_mu * s.transmittance_r);
  const auto e2 = static_cast<std::size_t>(s.irradiance_mu_s * s.irradiance_r);
  const auto s3 = static_cast<std::size_t>(sw) * static_cast<std::size_t>(sh) * static_cast<std::size_t>(sd);
  out.transmittance = readBack(transmittance, t2);
  out.irradiance = readBack(irradiance, e2);
  out.scattering = readBack(scattering, s3);
  out.single_mie = readBack(single_mie, s3);
  const GLuint textures[] = {transmittance, delta_irradiance, irradiance, delta_rayleigh, delta_mie,
                             scattering, single_mie, delta_multiple, delta_density};
  glDeleteTextures(9, textures);
  for (GLuint p : programs) glDeleteProgram(p);
  return out;
}

TEST(AtmosphereGpu, ComputePassesMatchTheCpuReferenceAndRepeat) {
  GlContext gl;
  if (!gl.create()) GTEST_SKIP() << "no OpenGL 4.5 context through EGL";
  std::printf("GL_RENDERER: %s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));

  ModelConfig c = testing::oneGroupConfig();
  // SKYIG_ATMOSPHERE_GPU_FULL=1: the default (Bruneton-size) tables, for measuring; the CPU
  // reference then takes minutes unless it is in the cache already.
  const char* full = std::getenv("SKYIG_ATMOSPHERE_GPU_FULL");
  if (full && std::string(full) == "1") c.sizes = TableSizes{};
  const AtmosphereModel model = testing::cachedModel(c);  // the CPU reference (float-rounded)
  const AtmosphereParameters& atm = model.parameters(0);
  const GroupTables& cpu = model.tables(0);
  const GpuTables gpu = runGpuPrecompute(atm, c.sizes, c.options.scattering_orders);

  const Stats t = compare(gpu.transmittance, cpu.transmittance.texels);
  const Stats e = compare(gpu.irradiance, cpu.irradiance.texels);
  const Stats sc = compare(gpu.scattering, cpu.scattering.texels);
  const Stats m = compare(gpu.single_mie, cpu.single_mie.texels);
  std::printf("GPU precompute (%d x %d x %d x %d tables, %d orders, one group of 4 wavelengths) "
              "%.3f s; GPU vs "
              "CPU relative difference median / 99th percentile: T %.2g / %.2g, E %.2g / %.2g, "
              "S %.2g / %.2g, single Mie %.2g / %.2g\n",
              c.sizes.scattering_r, c.sizes.scattering_mu, c.sizes.scattering_mu_s,
              c.sizes.scattering_nu, c.options.scattering_orders, gpu.seconds, t.median, t.p99, e.median, e.p99,
              sc.median, sc.p99, m.median, m.p99);
  // Float on the GPU against double on the CPU, through the whole chain of orders (measured
  // on llvmpipe, 99th percentiles: small tables 1e-4 to 6e-4, default tables up to 3.1e-3
  // for the single Mie table).
  EXPECT_LT(t.p99, 1e-3);
  EXPECT_LT(sc.median, 1e-4);
  EXPECT_LT(sc.p99, 3e-3);
  EXPECT_LT(m.p99, 5e-3);
  EXPECT_LT(e.p99, 1e-3);

  // Two precomputations with the same parameters give identical tables.
  const GpuTables again = runGpuPrecompute(atm, c.sizes, c.options.scattering_orders);
  EXPECT_TRUE(again.transmittance == gpu.transmittance);
  EXPECT_TRUE(again.irradiance == gpu.irradiance);
  EXPECT_TRUE(again.scattering == gpu.scattering);
  EXPECT_TRUE(again.single_mie == gpu.single_mie);
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
  GlContext gl;
  if (!gl.create()) GTEST_SKIP() << "no OpenGL 4.5 context through EGL";
  const AtmosphereModel model = testing::cachedModel(testing::oneGroupConfig());
  const AtmosphereParameters& atm = model.parameters(0);
  const GroupTables& t = model.tables(0);
  const Medium& m = model.config().medium;
  glBindTextureUnit(0, upload2D(t.transmittance));
  glBindTextureUnit(1, upload3D(t.scattering));
  glBindTextureUnit(2, upload3D(t.single_mie));
  glBindTextureUnit(3, upload2D(t.irradiance));
  const GLuint program = computeProgram("sky_view.comp");
  setParameters(program, atm);
  const int width = 1920;
  const int height = 1200;
  const GLuint out = texture2D(width, height);
  image(0, out, GL_WRITE_ONLY);

  struct Case {
    double altitude, sun_zenith_deg;
  };
  for (const Case& k : {Case{1000.0, 30.0}, Case{0.0, 90.0}, Case{100e3, 95.0}, Case{1000.0, 108.0}}) {
    const glm::dvec3 camera = observerPosition(m, k.altitude);
    const glm::dvec3 sun = directionFromAngles(k.sun_zenith_deg * kDegree, 0.0);
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
    EXPECT_EQ(bad, 0) << "altitude " << k.altitude << " sun zenith " << k.sun_zenith_deg;
    std::printf("sky panorama %dx%d, altitude %.0f m, sun zenith %.0f deg: %.1f ms (%.0f ns per "
                "pixel for 4 wavelengths), %d NaN/Inf/negative values\n",
                width, height, k.altitude, k.sun_zenith_deg, seconds * 1e3,
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
        const double disc_ground = rmu * rmu - r * r + m.bottom_radius_m * m.bottom_radius_m;
        Spectrum ground(4, 0.0);
        if (rmu < 0.0 && disc_ground >= 0.0) {
          const glm::dvec3 point = camera + view * (-rmu - std::sqrt(disc_ground));
          Spectrum tr;
          const Spectrum total = model.groundRadiance(camera, point, sun, &tr);
          const Spectrum in = model.skyRadianceToPoint(camera, point, sun);
          for (std::size_t i = 0; i < 4; ++i) ground[i] = total[i] - in[i];
        }
        for (std::size_t i = 0; i < 4; ++i) {
          const double e = expected[i] + disc[i] + ground[i];
          const double g = pixels[(static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x)) * 4 + i];
          EXPECT_NEAR(g, e, 2e-3 * e + 1e-9) << "pixel " << x << "," << y << " band " << i
                                             << " altitude " << k.altitude << " sun " << k.sun_zenith_deg;
        }
      }
    }
  }
}

}  // namespace
}  // namespace skyig::atmosphere
