#include "render/physical_sky_pass.h"

#include "render/gl_context.h"

#include <algorithm>
#include <string>

namespace skyig::render {

void setAtmosphereUniforms(GLuint program, const std::string& uniform, const atmosphere::AtmosphereParameters& a) {
  const std::string prefix = uniform + ".";
  auto v4 = [&](const char* name, const glm::dvec4& v) {
    glProgramUniform4f(program, glGetUniformLocation(program, (prefix + name).c_str()), static_cast<float>(v.x),
                       static_cast<float>(v.y), static_cast<float>(v.z), static_cast<float>(v.w));
  };
  auto f1 = [&](const char* name, double v) {
    glProgramUniform1f(program, glGetUniformLocation(program, (prefix + name).c_str()), static_cast<float>(v));
  };
  v4("solar_irradiance", a.solar_irradiance);
  f1("sun_angular_radius", a.sun_angular_radius);
  v4("limb_darkening_exponent", a.limb_darkening_exponent);
  f1("bottom_radius", a.bottom_radius);
  f1("top_radius", a.top_radius);
  v4("rayleigh_scattering", a.rayleigh_scattering);
  f1("rayleigh_scale_height", a.rayleigh_scale_height);
  v4("mie_scattering", a.mie_scattering);
  v4("mie_extinction", a.mie_extinction);
  f1("mie_scale_height", a.mie_scale_height);
  f1("mie_phase_g", a.mie_phase_g);
  v4("absorption_extinction", a.absorption_extinction);
  f1("ozone_center_altitude", a.ozone_center_altitude);
  f1("ozone_half_width", a.ozone_half_width);
  v4("ground_albedo", a.ground_albedo);
  f1("mu_s_min", a.mu_s_min);
  f1("transmittance_width", a.transmittance_width);
  f1("transmittance_height", a.transmittance_height);
  f1("irradiance_width", a.irradiance_width);
  f1("irradiance_height", a.irradiance_height);
  f1("scattering_r_size", a.scattering_r_size);
  f1("scattering_mu_size", a.scattering_mu_size);
  f1("scattering_mu_s_size", a.scattering_mu_s_size);
  f1("scattering_nu_size", a.scattering_nu_size);
}

namespace {

// Half floats would do for the sky (16 MB budget, docs/atmosphere.md); the tables go up as
// 32-bit floats until the packing of issue 5 lands.
GLuint upload2D(const shader::cpu_texture::sampler2D& s) {
  std::vector<float> texels;
  texels.reserve(s.texels.size() * 4);
  for (const glm::dvec4& t : s.texels)
    for (int c = 0; c < 4; ++c) texels.push_back(static_cast<float>(t[c]));
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  glTextureStorage2D(id, 1, GL_RGBA32F, s.width, s.height);
  glTextureSubImage2D(id, 0, 0, 0, s.width, s.height, GL_RGBA, GL_FLOAT, texels.data());
  for (GLenum p : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T}) glTextureParameteri(id, p, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  return id;
}

GLuint upload3D(const shader::cpu_texture::sampler3D& s) {
  std::vector<float> texels;
  texels.reserve(s.texels.size() * 4);
  for (const glm::dvec4& t : s.texels)
    for (int c = 0; c < 4; ++c) texels.push_back(static_cast<float>(t[c]));
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_3D, 1, &id);
  glTextureStorage3D(id, 1, GL_RGBA32F, s.width, s.height, s.depth);
  glTextureSubImage3D(id, 0, 0, 0, 0, s.width, s.height, s.depth, GL_RGBA, GL_FLOAT, texels.data());
  for (GLenum p : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) glTextureParameteri(id, p, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  return id;
}

}  // namespace

glm::dvec3 physicalCamera(const atmosphere::AtmosphereModel& model, double heightM) {
  // At least a metre above the ground: the tables' parameterisation is singular on it.
  return {0.0, 0.0, model.parameters(0).bottom_radius + std::max(heightM, 1.0)};
}

PhysicalSkyPass::PhysicalSkyPass()
    : program_("passes/fullscreen.vert", "passes/physical_sky.frag"),
      cameraLocation_(glGetUniformLocation(program_.id(), "camera")),
      sunLocation_(glGetUniformLocation(program_.id(), "sunDirectionP")) {}

PhysicalSkyPass::~PhysicalSkyPass() { release(); }

void PhysicalSkyPass::release() {
  if (!textures_.empty()) glDeleteTextures(static_cast<GLsizei>(textures_.size()), textures_.data());
  textures_.clear();
  current_ = nullptr;
}

void PhysicalSkyPass::use(const atmosphere::AtmosphereModel& model) {
  if (current_ == &model) return;
  if (model.groupCount() > static_cast<std::size_t>(kMaxGroups))
    throw GlContextError("the physical sky pass takes at most " + std::to_string(kMaxGroups * 4) + " wavelengths");
  release();
  groups_ = static_cast<int>(model.groupCount());
  const GLuint p = program_.id();
  glProgramUniform1i(p, glGetUniformLocation(p, "groupCount"), groups_);
  for (int g = 0; g < groups_; ++g) {
    const atmosphere::GroupTables& t = model.tables(static_cast<std::size_t>(g));
    textures_.push_back(upload2D(t.transmittance));
    textures_.push_back(upload3D(t.scattering));
    textures_.push_back(upload3D(t.single_mie));
    textures_.push_back(upload2D(t.irradiance));
    setAtmosphereUniforms(p, "atm[" + std::to_string(g) + "]", model.parameters(static_cast<std::size_t>(g)));
    // Columns: the linear Rec.709 (cd/m^2) of one unit of spectral radiance at each wavelength.
    glm::mat4 toRec709(0.0f);
    for (int k = 0; k < 4; ++k) {
      const std::size_t i = static_cast<std::size_t>(4 * g + k);
      if (i >= model.wavelengths().size()) continue;
      const glm::dvec3 xyz = model.converter().weight(i);
      const glm::dvec3 rgb = atmosphere::xyzToRec709(xyz);
      toRec709[k] = glm::vec4(glm::dvec4(rgb, 0.0));
    }
    glProgramUniformMatrix4fv(p, glGetUniformLocation(p, ("groupToRec709[" + std::to_string(g) + "]").c_str()), 1,
                              GL_FALSE, &toRec709[0][0]);
  }
  current_ = &model;
}

void PhysicalSkyPass::draw(const glm::dvec3& camera, const glm::dvec3& sunDirection) {
  const GLuint p = program_.id();
  glProgramUniform3f(p, cameraLocation_, static_cast<float>(camera.x), static_cast<float>(camera.y),
                     static_cast<float>(camera.z));
  glProgramUniform3f(p, sunLocation_, static_cast<float>(sunDirection.x), static_cast<float>(sunDirection.y),
                     static_cast<float>(sunDirection.z));
  for (int g = 0; g < groups_; ++g) {
    glBindTextureUnit(static_cast<GLuint>(0 + g), textures_[static_cast<std::size_t>(4 * g)]);
    glBindTextureUnit(static_cast<GLuint>(4 + g), textures_[static_cast<std::size_t>(4 * g + 1)]);
    glBindTextureUnit(static_cast<GLuint>(8 + g), textures_[static_cast<std::size_t>(4 * g + 2)]);
    glBindTextureUnit(static_cast<GLuint>(12 + g), textures_[static_cast<std::size_t>(4 * g + 3)]);
  }
  program_.use();
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace skyig::render
