#include "render/client/client_aerial_perspective.h"

#include "render/gl/shader_source.h"
#include "render/passes/common/atmosphere_uniforms.h"
#include "render/client/fog_uniforms.h"
#include "physics/atmosphere/physical_camera.h"
#include "physics/spectrum/spectrum.h"

#include <stdexcept>
#include <string>

namespace skyig::render {

std::string clientAerialPerspectiveGlsl() {
  return hostShaderSource("render/client/client_aerial_perspective.glsl", "skyig_");
}

ClientAerialPerspective::~ClientAerialPerspective() { release(); }

void ClientAerialPerspective::release() {
  if (transmittance_[0] != 0) glDeleteTextures(kGroups, transmittance_.data());
  transmittance_ = {};
  model_.reset();
}

bool ClientAerialPerspective::needsUpload(const PhysicalSkyPass::Tables& tables) const {
  return tables.model && model_.lock() != tables.model;
}

void ClientAerialPerspective::upload(const PhysicalSkyPass::Tables& tables) {
  if (!needsUpload(tables)) return;
  const atmosphere::AtmosphereModel& model = *tables.model;
  if (model.groupCount() > static_cast<std::size_t>(kGroups))
    throw std::invalid_argument("aerial perspective: the model has " + std::to_string(model.wavelengths().size()) +
                                " wavelengths, the GLSL sums at most " + std::to_string(4 * kGroups));
  release();
  for (std::size_t g = 0; g < static_cast<std::size_t>(kGroups); ++g)
    transmittance_[g] = uploadTable2D(model.tables(g < model.groupCount() ? g : 0).transmittance);
  // Sunlight through the segment per Rec.709 channel, as sky::clientAerialPerspective weighs it:
  // each wavelength's Rec.709 weight times the sun's spectrum (scaled to luminance 1).
  const atmosphere::Spectrum solar = model.solarRadiance();
  std::array<glm::dvec3, 4 * kGroups> w{};
  glm::dvec3 sum(0.0);
  for (std::size_t i = 0; i < solar.size(); ++i) {
    w[i] = atmosphere::xyzToRec709(model.converter().weight(i)) * solar[i];
    sum += w[i];
  }
  const double luminance = 0.2126729 * sum.x + 0.7151522 * sum.y + 0.0721750 * sum.z;
  for (std::size_t i = 0; i < w.size(); ++i) sunRec709_[i] = glm::vec3(w[i] / luminance);
  model_ = tables.model;
}

void ClientAerialPerspective::bind(const PhysicalSkyPass::Tables& tables, const skyig::sky::SkyState& state,
                                 GLuint program, int firstUnit) const {
  if (!tables.model || model_.lock() != tables.model)
    throw std::invalid_argument("aerial perspective: the physical sky's tables are not on the GPU yet");
  GLint linked = GL_FALSE;
  if (program == 0 || !glIsProgram(program) || (glGetProgramiv(program, GL_LINK_STATUS, &linked), linked != GL_TRUE))
    throw std::invalid_argument("aerial perspective: program " + std::to_string(program) +
                                " is not a linked program of the current context");
  GLint maxUnits = 0;
  glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &maxUnits);
  if (firstUnit < 0 || firstUnit + kUnits > maxUnits)
    throw std::invalid_argument("aerial perspective: texture units " + std::to_string(firstUnit) + " to " +
                                std::to_string(firstUnit + kUnits - 1) + " are not within 0 to " +
                                std::to_string(maxUnits - 1));
  auto sampler = [&](int i, GLuint texture, const std::string& name) {
    const GLuint unit = static_cast<GLuint>(firstUnit + i);
    glBindTextureUnit(unit, texture);
    glBindSampler(unit, 0);  // the tables' own filtering (linear, clamped)
    glProgramUniform1i(program, glGetUniformLocation(program, name.c_str()), firstUnit + i);
  };
  sampler(0, tables.scattering, "skyig_scattering");
  sampler(1, tables.singleMieRg, "skyig_singleMie");
  for (int g = 0; g < kGroups; ++g)
    sampler(2 + g, transmittance_[static_cast<std::size_t>(g)], "skyig_transmittance[" + std::to_string(g) + "]");
  glProgramUniform3fv(program, glGetUniformLocation(program, "skyig_sunRec709"), 4 * kGroups, &sunRec709_[0].x);
  // The tables' model's parameters: during a change of weather the tables drawn may still be the
  // previous model's for a few frames; both share the planet, so the camera is the same.
  setAtmosphereUniforms(program, "skyig_atm", tables.model->parameters(0));
  auto v3 = [&](const char* name, const glm::dvec3& v) {
    const glm::vec3 f(v);
    glProgramUniform3f(program, glGetUniformLocation(program, name), f.x, f.y, f.z);
  };
  const glm::dvec3 camera = atmosphere::physicalCamera(*tables.model, state.observer.heightM);
  v3("skyig_camera", camera);
  FogUniforms(program, "skyig_fog", "skyig_cameraHeight")
      .set(program, skyig::sky::drawnFogLayers(state.fog), glm::length(camera) - tables.model->parameters(0).bottom_radius);
  v3("skyig_sunDirection", skyig::sky::enuDirection(state.sunAzimuth, state.sunAltitude));
  v3("skyig_moonDirection", state.moonDirection);
  // As the CPU's: the moonlit in-scatter whenever the moon lights the sky at all.
  v3("skyig_moonlightScale", state.moonlightScale);
}

}  // namespace skyig::render
