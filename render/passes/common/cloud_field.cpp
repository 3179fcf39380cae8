#include "render/passes/common/cloud_field.h"

#include <glm/glm.hpp>

namespace skyig::render {

namespace {
bool drawnBroken(const CloudCovers& cover, const weather::FogLayers& layers, std::size_t k) {
  return cover[k].broken && layers[weather::kWeatherLayerCount + k].extinction > 0.0;
}
}  // namespace

int brokenDeckCount(const CloudCovers& cover, const weather::FogLayers& layers) {
  int n = 0;
  for (std::size_t k = 0; k < cover.size(); ++k)
    if (drawnBroken(cover, layers, k)) ++n;
  return n;
}

CloudFieldLocations::CloudFieldLocations(GLuint program)
    : shape(glGetUniformLocation(program, "cloudDeckShape")),
      place(glGetUniformLocation(program, "cloudDeckPlace")),
      along(glGetUniformLocation(program, "cloudDeckAlong")),
      eye(glGetUniformLocation(program, "cloudEye")) {}

void setCloudField(GLuint program, const CloudFieldLocations& at, const CloudCovers& cover,
                   const weather::FogLayers& layers, double heightM, double bottomRadiusM) {
  if (!at.present()) return;
  std::array<glm::vec4, sky::kCloudLayers> shape{}, place{}, along{};
  int n = 0;
  for (std::size_t k = 0; k < cover.size(); ++k) {
    if (!drawnBroken(cover, layers, k)) continue;
    const weather::CloudCover& c = cover[k];
    shape[n] = glm::vec4(glm::dvec4(c.midHeightM, c.cellM, c.threshold, c.softness));
    place[n] = glm::vec4(glm::dvec4(c.origin, c.stretch, c.seed));
    along[n] = glm::vec4(glm::dvec4(c.along, c.coverage, weather::kCloudFadeCells * c.cellM));
    ++n;
  }
  if (n == 0) return;
  glProgramUniform4fv(program, at.shape, n, &shape[0][0]);
  glProgramUniform4fv(program, at.place, n, &place[0][0]);
  glProgramUniform4fv(program, at.along, n, &along[0][0]);
  glProgramUniform2f(program, at.eye, static_cast<float>(heightM), static_cast<float>(bottomRadiusM));
}

}  // namespace skyig::render
