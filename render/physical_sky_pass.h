#pragma once
// The GPU side of the physical atmosphere: a model's tables as textures (up to four groups of
// four wavelengths) and the sky pass that renders from them (shaders/passes/physical_sky.frag).
#include "render/atmosphere/model.h"
#include "render/gl_program.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace skyig::render {

class PhysicalSkyPass {
 public:
  PhysicalSkyPass();
  ~PhysicalSkyPass();
  PhysicalSkyPass(const PhysicalSkyPass&) = delete;
  PhysicalSkyPass& operator=(const PhysicalSkyPass&) = delete;

  // Uploads the model's tables and parameters, unless they are already the current ones.
  void use(const atmosphere::AtmosphereModel& model);
  // Draws into the bound target: camera in metres from the planet's centre and the sun's
  // direction, both in the local east-north-up frame. The frame block must be bound.
  void draw(const glm::dvec3& camera, const glm::dvec3& sunDirection);

  static constexpr int kMaxGroups = 4;

 private:
  void release();
  GlProgram program_;
  GLint cameraLocation_ = -1;  // looked up once: draw() runs every frame
  GLint sunLocation_ = -1;
  const atmosphere::AtmosphereModel* current_ = nullptr;
  int groups_ = 0;
  std::vector<GLuint> textures_;  // per group: transmittance, scattering, single Mie, irradiance
};

// Sets every member of a GLSL `uniform AtmosphereParameters` named `uniform` (e.g. "atm" or
// "atm[2]") in `program` (shaders/atmosphere/parameters.glsl), as floats.
void setAtmosphereUniforms(GLuint program, const std::string& uniform, const atmosphere::AtmosphereParameters& a);

// The camera of an observer at `heightM` above the model's ground, on the local vertical.
glm::dvec3 physicalCamera(const atmosphere::AtmosphereModel& model, double heightM);

}  // namespace skyig::render
