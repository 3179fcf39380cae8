#include "physics/weather/fog_table.h"

#include <algorithm>
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

// The layers in the order a view meets them, the farthest first (each composes over what lies
// behind it), by their bottoms: looking up the highest is the farthest, looking down the lowest.
// Layers with one bottom keep their order (the weather's three all stand on the ground), so they
// compose as before the decks came; a deck the eye is in counts as beyond the ground's layers
// looking up (they are mostly below it) and before them looking down.
std::array<std::size_t, kFogLayerCount> farthestFirst(const FogLayers& layers, double mu) {
  std::array<std::size_t, kFogLayerCount> order{};
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  const auto key = [&](std::size_t i) { return mu >= 0.0 ? layers[i].bottom_height : -layers[i].bottom_height; };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key(a) > key(b); });
  return order;
}

// d < 0: the whole ray (to the ground where it meets it).
// The air's transmittance from the eye to where the view enters deck f (1 inside it, or without
// `air`).
double airBefore(const FogLayer& f, double heightM, double mu, const AirTransmittance& air) {
  if (!air) return 1.0;
  const double base = f.bottom_height - shader::fogBottomBand(f), top = f.top_height + f.band_height;
  if (heightM >= base && heightM <= top) return 1.0;
  const double d = shader::distanceToHeight(f.planet_radius, heightM, mu, heightM < base ? base : top);
  return d > 0.0 ? air(mu, d) : 1.0;
}

glm::dvec4 compose(const FogLayers& layers, const std::array<FogEye, kFogLayerCount>& eyes, double heightM, double mu,
                   double segment, const AirTransmittance& air) {
  glm::dvec3 light(0.0);
  double t = 1.0;
  for (const std::size_t i : farthestFirst(layers, mu)) {
    const FogLayer& f = layers[i];
    if (f.extinction <= 0.0) continue;
    const double d = segment >= 0.0 ? segment : rayEnd(f.planet_radius, heightM, mu);
    // A view down to the ground from under a deck never meets it, and all it sees (the ground,
    // the air and the layers below) is in its shade; one that grazes past the ground's horizon
    // goes on up into it.
    if (i >= kWeatherLayerCount && rayEnd(f.planet_radius, heightM, mu) < kBeyondTheLayers &&
        heightM < f.bottom_height - shader::fogBottomBand(f)) {
      const double shade = shader::fogShadeBelow(f);
      light *= shade;
      t *= shade;
      continue;
    }
    const double through = shader::fogTransmittance(f, heightM, mu, d);
    const double seen = i >= kWeatherLayerCount ? airBefore(f, heightM, mu, air) : 1.0;
    if (seen == 1.0) {  // nothing in front (the weather's own layers are about the eye)
      light = shader::throughFogSeen(f, eyes[i], light, heightM, mu, d);
      t *= through;
      continue;
    }
    // What of the clear air's light along the view stays: the deck's transmittance of what lies
    // beyond it, and the air's own light in front of it, which under the deck is in its shade.
    const bool under = heightM < f.bottom_height - shader::fogBottomBand(f);
    const double front = (1.0 - seen) * (under ? shader::fogShadeBelow(f) : 1.0);
    const double kept = front + seen * through;
    light = light * kept + seen * shader::throughFogSeen(f, eyes[i], glm::dvec3(0.0), heightM, mu, d);
    t *= kept;
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

glm::dvec4 fogAlong(const FogLayers& layers, double heightM, double mu, const AirTransmittance& air) {
  return compose(layers, eyesOf(layers, heightM), heightM, mu, -1.0, air);
}

glm::dvec4 fogAlong(const FogLayers& layers, double heightM, double mu, double d, const AirTransmittance& air) {
  return compose(layers, eyesOf(layers, heightM), heightM, mu, d, air);
}

std::vector<glm::vec4> fogTable(const FogLayers& layers, double heightM, int size, const AirTransmittance& air) {
  const std::array<FogEye, kFogLayerCount> eyes = eyesOf(layers, heightM);  // the slab solved once per layer
  std::vector<glm::vec4> table(static_cast<std::size_t>(size));
  for (int i = 0; i < size; ++i) {
    const double mu = shader::fogTableMu((i + 0.5) / size);
    table[static_cast<std::size_t>(i)] = glm::vec4(compose(layers, eyes, heightM, mu, -1.0, air));
  }
  return table;
}

}  // namespace skyig::weather
