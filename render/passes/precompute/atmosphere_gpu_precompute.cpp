#include "render/passes/precompute/atmosphere_gpu_precompute.h"

#include <glad/gl.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "physics/atmosphere/precompute/orders_tail.h"
#include "physics/atmosphere/precompute/precompute.h"
#include "render/gl/egl_context.h"
#include "render/gl/gl_context.h"
#include "render/passes/common/atmosphere_uniforms.h"
#include "render/gl/gl_program.h"
#include "render/gl/shader_source.h"
#include "render/glsl/bindings.h"

namespace skyig::render {

using atmosphere::AtmosphereParameters;
using atmosphere::GroupTables;
using atmosphere::ModelConfig;
using Clock = std::chrono::steady_clock;

std::string describe(const GpuPrecomputeTiming& t) {
  char line[256];
  std::snprintf(line, sizeof line,
                "total %.2f s = compile %.2f, T %.3f, direct E %.3f, single %.2f, slices %.2f, density %.2f, "
                "indirect E %.2f, multiple %.2f, readback %.2f s",
                t.total, t.compile, t.transmittance, t.direct_irradiance, t.single_scattering, t.nu_slices,
                t.scattering_density, t.indirect_irradiance, t.multiple_scattering, t.readback);
  return line;
}

namespace {

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

GLuint compileCompute(const std::string& path) {
  return linkProgram({compileShaderStage(GL_COMPUTE_SHADER, path)}, path);
}

void setOrder(GLuint program, int order) {
  glProgramUniform1i(program, glGetUniformLocation(program, "scattering_order"), order);
}

void setFiltering(GLuint t) {
  glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
    glTextureParameteri(t, wrap, GL_CLAMP_TO_EDGE);
}

// RGBA32F throughout: the tables leave as float32 (the cache's precision) and the deltas feed
// the next order, so half floats would add error at every order.
GLuint texture2D(int w, int h) {
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &t);
  glTextureStorage2D(t, 1, GL_RGBA32F, w, h);
  setFiltering(t);
  return t;
}

GLuint texture3D(int w, int h, int d) {
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_3D, 1, &t);
  glTextureStorage3D(t, 1, GL_RGBA32F, w, h, d);
  setFiltering(t);
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearTexImage(t, 0, GL_RGBA, GL_FLOAT, zero);
  return t;
}

GLuint texture1DArray(int w, int layers) {
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_1D_ARRAY, 1, &t);
  glTextureStorage2D(t, 1, GL_RGBA32F, w, layers);
  setFiltering(t);
  return t;
}

void image(GLuint unit, GLuint t, GLenum access) { glBindImageTexture(unit, t, 0, GL_TRUE, 0, access, GL_RGBA32F); }

void download(GLuint t, std::vector<glm::dvec4>& texels) {
  std::vector<float> v(texels.size() * 4);
  glGetTextureImage(t, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(v.size() * sizeof(float)), v.data());
  for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = glm::dvec4(v[4 * i], v[4 * i + 1], v[4 * i + 2], v[4 * i + 3]);
}

GLuint groups(int size, int local) { return static_cast<GLuint>((size + local - 1) / local); }

}  // namespace

// Local sizes must match the layout() declarations of the .comp files.
struct AtmosphereGpuPrecompute::Programs {
  GLuint transmittance = compileCompute("render/passes/precompute/precompute_transmittance.comp");
  GLuint direct = compileCompute("render/passes/precompute/precompute_direct_irradiance.comp");
  GLuint ray = compileCompute("render/passes/precompute/precompute_ray_transmittance.comp");
  GLuint single = compileCompute("render/passes/precompute/precompute_single_scattering.comp");
  GLuint slices = compileCompute("render/passes/precompute/precompute_nu_slices.comp");
  GLuint density = compileCompute("render/passes/precompute/precompute_scattering_density.comp");
  GLuint density_order2 = compileCompute("render/passes/precompute/precompute_scattering_density_order2.comp");
  GLuint indirect = compileCompute("render/passes/precompute/precompute_indirect_irradiance.comp");
  GLuint multiple = compileCompute("render/passes/precompute/precompute_multiple_scattering.comp");
  std::array<GLuint, 9> all() const {
    return {transmittance, direct, ray, single, slices, density, density_order2, indirect, multiple};
  }
  ~Programs() {
    for (GLuint p : all()) glDeleteProgram(p);
  }
};

AtmosphereGpuPrecompute::AtmosphereGpuPrecompute() {
  const auto start = Clock::now();
  programs_ = std::make_unique<Programs>();
  compile_seconds_ = since(start);
}

AtmosphereGpuPrecompute::~AtmosphereGpuPrecompute() = default;

namespace {

constexpr int kDensityThetaSamples = 16;  // ATMOSPHERE_DENSITY_ANGULAR_SAMPLES
// precompute_ray_transmittance.comp: the sample points 0..n of the single and multiple
// scattering integrals along each ray, the same for both.
namespace glsl = shader::atmosphere_types;
static_assert(glsl::ATMOSPHERE_SINGLE_SCATTERING_SAMPLES == glsl::ATMOSPHERE_MULTIPLE_SCATTERING_SAMPLES);
constexpr int kRaySamples = glsl::ATMOSPHERE_MULTIPLE_SCATTERING_SAMPLES + 1;
static_assert(kDensityThetaSamples == glsl::ATMOSPHERE_DENSITY_ANGULAR_SAMPLES);

// The textures of one group, reused for the next (every pass rewrites what it writes).
struct Textures {
  GLuint transmittance, delta_irradiance, irradiance, delta_rayleigh, delta_mie, scattering, single_mie,
      delta_multiple, delta_density, slices_a, slices_b, ray_transmittance, ray_geometry, ground_irradiance;
  Textures(const atmosphere::TableSizes& s, const atmosphere::TableSizes& density) {
    const int sw = s.scatteringNu * s.scatteringMuS;
    transmittance = texture2D(s.transmittanceMu, s.transmittanceR);
    delta_irradiance = texture2D(s.irradianceMuS, s.irradianceR);
    irradiance = texture2D(s.irradianceMuS, s.irradianceR);
    for (GLuint* t : {&delta_rayleigh, &delta_mie, &scattering, &single_mie, &delta_multiple})
      *t = texture3D(sw, s.scatteringMu, s.scatteringR);
    delta_density = texture3D(sw, density.scatteringMu, density.scatteringR);
    // precompute_nu_slices.comp: nu + 1 slices x (theta samples x mu_s) layers, of one radius.
    for (GLuint* t : {&slices_a, &slices_b}) *t = texture1DArray(s.scatteringNu + 1, kDensityThetaSamples * s.scatteringMuS);
    // precompute_ray_transmittance.comp: sample x mu x r.
    for (GLuint* t : {&ray_transmittance, &ray_geometry}) *t = texture3D(kRaySamples, s.scatteringMu, s.scatteringR);
    // The density's ground: the first row of delta_irradiance.
    glCreateTextures(GL_TEXTURE_1D, 1, &ground_irradiance);
    glTextureStorage1D(ground_irradiance, 1, GL_RGBA32F, s.irradianceMuS);
    setFiltering(ground_irradiance);
  }
  ~Textures() {
    const GLuint all[] = {transmittance, delta_irradiance, irradiance, delta_rayleigh, delta_mie,
                          scattering, single_mie, delta_multiple, delta_density, slices_a, slices_b,
                          ray_transmittance, ray_geometry, ground_irradiance};
    glDeleteTextures(14, all);
  }
  Textures(const Textures&) = delete;
  Textures& operator=(const Textures&) = delete;
};

}  // namespace

// One precompute's passes, group by group: the dispatches (cancellable between slices, timed
// when asked), a group's direct passes, each scattering order, and the readback.
class AtmosphereGpuPrecompute::Run {
 public:
  Run(const Programs& programs, const ModelConfig& config, const atmosphere::TableSizes& densitySizes,
      const GpuPrecomputeOptions& options, GpuPrecomputeTiming& timing)
      : p_(programs), s_(config.sizes), density_(densitySizes), options_(options), t_(timing),
        orders_(config.options.scatteringOrders), ordersTail_(config.options.ordersTail),
        sw_(s_.scatteringNu * s_.scatteringMuS), sh_(s_.scatteringMu), sd_(s_.scatteringR), x_(s_, densitySizes) {}

  GroupTables group(const AtmosphereParameters& params, std::size_t g, std::size_t groups) {
    const auto groupStart = Clock::now();
    prefix_ = "group " + std::to_string(g + 1) + "/" + std::to_string(groups) + ": ";
    bindParameters(params);
    directPasses();
    for (int order = 2; order <= orders_; ++order) scatteringOrder(order);
    GroupTables tables = readBack();
    if (tail()) {  // the CPU's code, on the last two orders read back
      shader::cpu_texture::sampler3D last(sw_, sh_, sd_);
      shader::cpu_texture::sampler2D lastIrradiance(s_.irradianceMuS, s_.irradianceR);
      download(x_.delta_multiple, last.texels);
      download(x_.delta_irradiance, lastIrradiance.texels);
      atmosphere::addOrdersTail(params, before_, last, lastIrradiance, tables);
    }
    if (options_.progress) {
      char line[96];
      std::snprintf(line, sizeof line, "group %zu/%zu done (%.1f s)", g + 1, groups, since(groupStart));
      options_.progress(line);
    }
    return tables;
  }

 private:
  // Each pass's local size is that of its .comp file (llvmpipe runs a workgroup's invocations
  // as SIMD lanes: 8 x 8, one radius per group, keeps the branches on the ground intersection
  // coherent). A 3D pass (local depth 1) runs one radius per dispatch, finished before the
  // next, so a cancellation waits for one slice (~1 s of llvmpipe at the default sizes'
  // costliest pass) instead of the whole pass (30 s).
  void dispatch(GLuint program, int width, int height, int depth, double& seconds, const std::string& name) {
    options_.control.begin(prefix_ + name);
    const auto passStart = Clock::now();
    GLint local[3] = {1, 1, 1};
    glGetProgramiv(program, GL_COMPUTE_WORK_GROUP_SIZE, local);
    glUseProgram(program);
    const GLint zOffset = glGetUniformLocation(program, "z_offset");
    const int slice = zOffset >= 0 ? local[2] : depth;
    for (int z = 0; z < depth; z += slice) {
      if (z > 0) {
        glFinish();
        options_.control.cancel.throwIfRequested();
      }
      if (zOffset >= 0) glUniform1i(zOffset, z);
      glDispatchCompute(groups(width, local[0]), groups(height, local[1]), groups(std::min(slice, depth - z), local[2]));
    }
    finishPass(passStart, seconds);
  }

  // One radius of a pass whose local depth is 1 (the slices and the density, interleaved).
  void dispatchRadius(GLuint program, int width, int height, int z, double& seconds) {
    const auto passStart = Clock::now();
    GLint local[3] = {1, 1, 1};
    glGetProgramiv(program, GL_COMPUTE_WORK_GROUP_SIZE, local);
    glUseProgram(program);
    glUniform1i(glGetUniformLocation(program, "z_offset"), z);
    glDispatchCompute(groups(width, local[0]), groups(height, local[1]), 1);
    finishPass(passStart, seconds);
  }

  void finishPass(Clock::time_point passStart, double& seconds) const {
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    if (options_.time_passes) {
      glFinish();
      seconds += since(passStart);
    }
  }

  // The group's parameters; the passes that read the density table also get its coarser sizes.
  void bindParameters(const AtmosphereParameters& params) {
    for (GLuint program : p_.all()) setAtmosphereUniforms(program, "atm", params);
    AtmosphereParameters densityParams = params;
    densityParams.scattering_r_size = density_.scatteringR;
    densityParams.scattering_mu_size = density_.scatteringMu;
    for (GLuint program : {p_.ray, p_.slices, p_.density, p_.density_order2, p_.multiple})
      setAtmosphereUniforms(program, "atm_density", densityParams);
    for (GLuint unit = 0; unit < SKYIG_PRECOMPUTE_UNIT_COUNT; ++unit) glBindTextureUnit(unit, 0);
  }

  // Bruneton & Neyret 2008, algorithm 4.1, lines 1-4: T, the direct irradiance, the
  // transmittance along each ray's samples, single scattering.
  void directPasses() {
    image(SKYIG_IMAGE_TRANSMITTANCE, x_.transmittance, GL_WRITE_ONLY);
    dispatch(p_.transmittance, s_.transmittanceMu, s_.transmittanceR, 1, t_.transmittance, "transmittance");
    glBindTextureUnit(SKYIG_UNIT_TRANSMITTANCE, x_.transmittance);
    image(SKYIG_IMAGE_DELTA_IRRADIANCE, x_.delta_irradiance, GL_WRITE_ONLY);
    image(SKYIG_IMAGE_IRRADIANCE, x_.irradiance, GL_WRITE_ONLY);
    dispatch(p_.direct, s_.irradianceMuS, s_.irradianceR, 1, t_.direct_irradiance, "direct irradiance");
    image(SKYIG_IMAGE_RAY_TRANSMITTANCE, x_.ray_transmittance, GL_WRITE_ONLY);
    image(SKYIG_IMAGE_RAY_GEOMETRY, x_.ray_geometry, GL_WRITE_ONLY);
    dispatch(p_.ray, kRaySamples, sh_, sd_, t_.transmittance, "transmittance along the rays");
    glBindTextureUnit(SKYIG_UNIT_RAY_TRANSMITTANCE, x_.ray_transmittance);
    glBindTextureUnit(SKYIG_UNIT_RAY_GEOMETRY, x_.ray_geometry);
    image(SKYIG_IMAGE_DELTA_RAYLEIGH, x_.delta_rayleigh, GL_WRITE_ONLY);
    image(SKYIG_IMAGE_DELTA_MIE, x_.delta_mie, GL_WRITE_ONLY);
    image(SKYIG_IMAGE_SCATTERING, x_.scattering, GL_WRITE_ONLY);
    image(SKYIG_IMAGE_SINGLE_MIE, x_.single_mie, GL_WRITE_ONLY);
    dispatch(p_.single, sw_, sh_, sd_, t_.single_scattering, "single scattering");
  }

  // Algorithm 4.1, lines 5-10, for one order: the scattering density, the indirect irradiance,
  // the multiple scattering it adds.
  void scatteringOrder(int order) {
    const std::string orderText = ", order " + std::to_string(order) + "/" + std::to_string(orders_);
    scatteringDensity(order, orderText);
    // delta_irradiance and delta_multiple are rewritten next: unbind them as samplers.
    glBindTextureUnit(SKYIG_UNIT_DELTA_IRRADIANCE, 0);
    image(SKYIG_IMAGE_DELTA_IRRADIANCE, x_.delta_irradiance, GL_WRITE_ONLY);
    image(SKYIG_IMAGE_IRRADIANCE, x_.irradiance, GL_READ_WRITE);
    setOrder(p_.indirect, order);
    dispatch(p_.indirect, s_.irradianceMuS, s_.irradianceR, 1, t_.indirect_irradiance, "indirect irradiance" + orderText);
    glBindTextureUnit(SKYIG_UNIT_DELTA_MULTIPLE, 0);
    glBindTextureUnit(SKYIG_UNIT_DELTA_DENSITY, x_.delta_density);
    if (tail() && order == orders_) {  // keep the order before the last for the tail
      before_ = shader::cpu_texture::sampler3D(sw_, sh_, sd_);
      download(x_.delta_multiple, before_.texels);
    }
    image(SKYIG_IMAGE_DELTA_MULTIPLE, x_.delta_multiple, GL_WRITE_ONLY);
    image(SKYIG_IMAGE_SCATTERING, x_.scattering, GL_READ_WRITE);
    dispatch(p_.multiple, sw_, sh_, sd_, t_.multiple_scattering, "multiple scattering" + orderText);
  }

  // Radius by radius, the nu slices of that radius then its density (the slices hold one
  // radius: an array texture's layers are limited, 2048 on llvmpipe).
  void scatteringDensity(int order, const std::string& orderText) {
    glBindTextureUnit(SKYIG_UNIT_DELTA_RAYLEIGH, x_.delta_rayleigh);
    glBindTextureUnit(SKYIG_UNIT_DELTA_MIE, x_.delta_mie);
    glBindTextureUnit(SKYIG_UNIT_DELTA_MULTIPLE, x_.delta_multiple);
    glBindTextureUnit(SKYIG_UNIT_DELTA_IRRADIANCE, x_.delta_irradiance);
    glCopyImageSubData(x_.delta_irradiance, GL_TEXTURE_2D, 0, 0, 0, 0, x_.ground_irradiance, GL_TEXTURE_1D, 0, 0, 0, 0,
                       s_.irradianceMuS, 1, 1);
    glBindTextureUnit(SKYIG_UNIT_GROUND_IRRADIANCE, x_.ground_irradiance);
    glBindTextureUnit(SKYIG_UNIT_NU_SLICES_A, x_.slices_a);
    glBindTextureUnit(SKYIG_UNIT_NU_SLICES_B, x_.slices_b);
    setOrder(p_.slices, order);
    const GLuint density = order == 2 ? p_.density_order2 : p_.density;
    options_.control.begin(prefix_ + "scattering density" + orderText);
    for (int z = 0; z < density_.scatteringR; ++z) {
      if (z > 0) {
        glFinish();
        options_.control.cancel.throwIfRequested();
      }
      image(SKYIG_IMAGE_NU_SLICES_A, x_.slices_a, GL_WRITE_ONLY);
      image(SKYIG_IMAGE_NU_SLICES_B, x_.slices_b, GL_WRITE_ONLY);
      dispatchRadius(p_.slices, s_.scatteringNu + 1, kDensityThetaSamples * s_.scatteringMuS, z, t_.nu_slices);
      image(SKYIG_IMAGE_DELTA_DENSITY, x_.delta_density, GL_WRITE_ONLY);
      dispatchRadius(density, sw_, density_.scatteringMu, z, t_.scattering_density);
    }
  }

  GroupTables readBack() {
    const auto readStart = Clock::now();
    GroupTables tables;
    tables.transmittance = shader::cpu_texture::sampler2D(s_.transmittanceMu, s_.transmittanceR);
    tables.irradiance = shader::cpu_texture::sampler2D(s_.irradianceMuS, s_.irradianceR);
    tables.scattering = shader::cpu_texture::sampler3D(sw_, sh_, sd_);
    tables.singleMie = shader::cpu_texture::sampler3D(sw_, sh_, sd_);
    download(x_.transmittance, tables.transmittance.texels);
    download(x_.irradiance, tables.irradiance.texels);
    download(x_.scattering, tables.scattering.texels);
    download(x_.single_mie, tables.singleMie.texels);
    t_.readback += since(readStart);
    return tables;
  }

  const Programs& p_;
  const atmosphere::TableSizes& s_;
  const atmosphere::TableSizes& density_;
  const GpuPrecomputeOptions& options_;
  GpuPrecomputeTiming& t_;
  bool tail() const { return ordersTail_ && orders_ >= 3; }

  const int orders_;
  const bool ordersTail_;
  const int sw_, sh_, sd_;
  shader::cpu_texture::sampler3D before_;  // the order before the last (tail())
  Textures x_;
  std::string prefix_;
};

namespace {

// What the GPU path cannot compute, said before any work: bad orders, wavelengths, medium or
// sizes (std::invalid_argument), or an OpenGL whose array textures are too small for the
// slices (std::runtime_error: the loader's "auto" then falls back to the CPU).
void checkGpuPrecompute(const ModelConfig& config) {
  const int orders = config.options.scatteringOrders;
  if (orders < 1 || orders > 32) {
    throw std::invalid_argument("atmosphere GPU precompute: scattering_orders = " + std::to_string(orders) +
                                " is invalid (expected 1 to 32)");
  }
  (void)atmosphere::SpectralConverter(config.wavelengthsNm);  // throws std::invalid_argument on bad wavelengths
}

void checkDensity(const ModelConfig& config, const GpuPrecomputeOptions& options) {
  if (options.density_divisor != 1 && options.density_divisor != 2) {
    throw std::invalid_argument("atmosphere GPU precompute: density_divisor = " +
                                std::to_string(options.density_divisor) + " is invalid (expected 1 or 2)");
  }
  GLint maxLayers = 0;
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
  const int muS = config.sizes.scatteringMuS;
  if (kDensityThetaSamples * muS > maxLayers) {
    throw std::runtime_error("atmosphere GPU precompute: " + std::to_string(muS) + " sun zenith angles need " +
                             std::to_string(kDensityThetaSamples * muS) + " layers of an array texture, this OpenGL has " +
                             std::to_string(maxLayers));
  }
}

}  // namespace

std::vector<GroupTables> AtmosphereGpuPrecompute::computeTables(const ModelConfig& config,
                                                                const GpuPrecomputeOptions& options,
                                                                GpuPrecomputeTiming* timing) {
  checkGpuPrecompute(config);
  // The groups as AtmosphereModel makes them (validates the medium and the sizes).
  const std::vector<AtmosphereParameters> params = atmosphere::groupParameters(config);
  checkDensity(config, options);
  // The density table: its view angles divided (mu stays even: half of it for the rays that
  // hit the ground).
  atmosphere::TableSizes densitySizes = config.sizes;
  densitySizes.scatteringMu = std::max(2, config.sizes.scatteringMu / options.density_divisor / 2 * 2);

  const auto start = Clock::now();
  GpuPrecomputeTiming t;
  t.compile = compile_seconds_;
  std::vector<GroupTables> out;
  {
    Run run(*programs_, config, densitySizes, options, t);
    for (std::size_t g = 0; g < params.size(); ++g) out.push_back(run.group(params[g], g, params.size()));
  }
  for (GLuint unit = 0; unit < SKYIG_PRECOMPUTE_UNIT_COUNT; ++unit) glBindTextureUnit(unit, 0);
  for (GLuint unit = 0; unit < SKYIG_PRECOMPUTE_IMAGE_COUNT; ++unit) glBindImageTexture(unit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
  glUseProgram(0);
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", error);
    throw std::runtime_error(std::string("atmosphere GPU precompute: OpenGL error ") + code);
  }
  t.total = compile_seconds_ + since(start);
  compile_seconds_ = 0.0;  // counted once
  if (timing) *timing = t;
  return out;
}

atmosphere::AtmosphereModel AtmosphereGpuPrecompute::compute(const ModelConfig& config,
                                                             const GpuPrecomputeOptions& options,
                                                             GpuPrecomputeTiming* timing) {
  return atmosphere::AtmosphereModel(config, computeTables(config, options, timing));
}

std::vector<GroupTables> precomputeTablesOnGpu(const ModelConfig& config, const GpuPrecomputeOptions& options,
                                               GpuPrecomputeTiming* timing) {
  const std::unique_ptr<GlContext> context = createWorkerHeadlessContext(options.display_threads);
  if (options.progress) options.progress("on " + context->info().renderer + " (" + context->info().platform + ")");
  AtmosphereGpuPrecompute precompute;
  return precompute.computeTables(config, options, timing);
}

}  // namespace skyig::render
