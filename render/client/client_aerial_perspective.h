#pragma once
// Aerial perspective in a client's own shaders (docs/library.md): the GLSL text a client pastes into
// its programs (render/client/client_aerial_perspective.glsl, every name prefixed skyig_)
// and the binding of the physical sky's tables and the state's lights to a program of the
// client's, so that skyigAerialPerspective() gives what sky::clientAerialPerspective gives on the CPU.
#include "render/passes/sky/physical_sky_pass.h"
#include "sky/sky_state.h"

#include <glad/gl.h>

#include <array>
#include <memory>
#include <string>

namespace skyig::render {

// The GLSL: no #version line, includes expanded, names prefixed skyig_; declares the skyig_
// uniforms and `vec3 skyigAerialPerspective(vec3 offsetEnuM, out vec3 transmittance)`.
std::string clientAerialPerspectiveGlsl();

class ClientAerialPerspective {
 public:
  // Wavelength groups (of four) the GLSL sums the transmittance over (SKYIG_AERIAL_GROUPS).
  static constexpr int kGroups = 4;
  // Texture units a binding takes from the first one the client names: the packed scattering and
  // single Mie tables, then the spectral transmittance table of each group.
  static constexpr int kUnits = 2 + kGroups;

  ClientAerialPerspective() = default;
  ~ClientAerialPerspective();
  ClientAerialPerspective(const ClientAerialPerspective&) = delete;
  ClientAerialPerspective& operator=(const ClientAerialPerspective&) = delete;

  // Whether `tables`' model's spectral transmittance tables still have to be uploaded (upload
  // does it; it changes GL state a guard must save: the caller's).
  bool needsUpload(const PhysicalSkyPass::Tables& tables) const;
  void upload(const PhysicalSkyPass::Tables& tables);

  // Binds `tables` (the pass's current ones, uploaded) to units firstUnit .. firstUnit + kUnits
  // - 1 (with no sampler object on them) and sets `program`'s skyig_ uniforms (glProgramUniform:
  // the program need not be in use) for `state`: the tables' atmosphere, the observer's camera,
  // the sun and the moon. Touches nothing else. Throws std::invalid_argument for a program that
  // is not a linked one of this context, units beyond GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, a
  // model of more than kGroups groups, or tables not uploaded.
  void bind(const PhysicalSkyPass::Tables& tables, const skyig::sky::SkyState& state, GLuint program,
            int firstUnit) const;

 private:
  void release();
  std::weak_ptr<const atmosphere::AtmosphereModel> model_;  // whose transmittance is uploaded
  std::array<GLuint, kGroups> transmittance_{};
  std::array<glm::vec3, 4 * kGroups> sunRec709_{};  // per wavelength, luminance 1 in all
};

}  // namespace skyig::render
