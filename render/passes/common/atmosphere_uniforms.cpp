#include "render/passes/common/atmosphere_uniforms.h"

#include <array>

#include "physics/atmosphere/aerosol_type.h"

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
  f1("mie_phase_tabulated", a.mie_phase_tabulated);
  std::array<float, atmosphere::kMiePhaseSamples> table{};
  for (std::size_t i = 0; i < table.size(); ++i) table[i] = static_cast<float>(a.mie_phase_log_table[i]);
  glProgramUniform1fv(program, glGetUniformLocation(program, (prefix + "mie_phase_log_table").c_str()),
                      static_cast<GLsizei>(table.size()), table.data());
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

}  // namespace skyig::render
