#include "physics/weather/fog_table.h"

#include <array>
#include <cmath>

namespace skyig::weather {

namespace {

// Far beyond any layer: a ray that misses the ground leaves them all.
constexpr double kBeyondTheLayers = 1e9;

// Distance to the ground sphere of radius R along mu from heightM above it, or kBeyondTheLayers.
double rayEnd(double R, double heightM, double mu) {
  const double r = R + heightM, b = r * mu;
  const double discriminant = b * b - heightM * (2.0 * R + heightM);
  return mu < 0.0 && discriminant >= 0.0 ? -b - std::sqrt(discriminant) : kBeyondTheLayers;
}

glm::dvec4 compose(const FogLayers& layers, const std::array<FogEye, kFogLayerCount>& eyes, double heightM, double mu) {
  glm::dvec3 light(0.0);
  double t = 1.0;
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const FogLayer& f = layers[i];
    if (f.extinction <= 0.0) continue;
    const double d = rayEnd(f.planet_radius, heightM, mu);
    light = shader::throughFogSeen(f, eyes[i], light, heightM, mu, d);
    t *= shader::fogTransmittance(f, heightM, mu, d);
  }
  return {light, t};
}

std::array<FogEye, kFogLayerCount> eyesOf(const FogLayers& layers, double heightM) {
  std::array<FogEye, kFogLayerCount> eyes{};
  for (std::size_t i = 0; i < layers.size(); ++i)
    if (layers[i].extinction > 0.0) eyes[i] = shader::fogEye(layers[i], heightM);
  return eyes;
}

}  // namespace

glm::dvec4 fogAlong(const FogLayers& layers, double heightM, double mu) {
  return compose(layers, eyesOf(layers, heightM), heightM, mu);
}

std::vector<glm::vec4> fogTable(const FogLayers& layers, double heightM, int size) {
  const std::array<FogEye, kFogLayerCount> eyes = eyesOf(layers, heightM);  // the slab solved once per layer
  std::vector<glm::vec4> table(static_cast<std::size_t>(size));
  for (int i = 0; i < size; ++i) {
    const double mu = shader::fogTableMu((i + 0.5) / size);
    table[static_cast<std::size_t>(i)] = glm::vec4(compose(layers, eyes, heightM, mu));
  }
  return table;
}

}  // namespace skyig::weather
