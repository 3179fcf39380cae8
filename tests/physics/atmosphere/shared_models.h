#pragma once
// Models shared by the atmosphere tests. CTest runs every test in its own process, so the
// tables go through the disk cache in the build tree: the first test to need a model
// precomputes it (seconds), the others load it (milliseconds). The cache is itself tested in
// cache_test.cpp.
#include <filesystem>
#include <memory>

#include "tables/table_cache.h"

namespace skyig::atmosphere::testing {

inline std::filesystem::path testCacheDirectory() {
  return std::filesystem::path(SKYIG_BINARY_DIR) / "atmosphere-test-cache";
}

// The Bruneton 2017 Earth at skyig's 16 wavelengths, small tables, 4 orders.
inline ModelConfig smallEarthConfig() {
  ModelConfig c;
  c.sizes = TableSizes::small();
  c.options.scatteringOrders = 4;
  return c;
}

// One group of four wavelengths (Bruneton & Neyret 2008's three and 830 nm), for tests that
// look at spectral radiance only.
inline ModelConfig oneGroupConfig() {
  ModelConfig c = smallEarthConfig();
  c.wavelengthsNm = {440.0, 550.0, 680.0, 830.0};
  return c;
}

// Tables a few texels on a side: physics too coarse to compare with references, but computed
// in well under a second, for tests of mechanisms (cache, updater, linearity).
inline TableSizes tinySizes() {
  TableSizes s;
  s.transmittanceMu = 16;
  s.transmittanceR = 8;
  s.irradianceMuS = 8;
  s.irradianceR = 4;
  s.scatteringR = 4;
  s.scatteringMu = 8;
  s.scatteringMuS = 4;
  s.scatteringNu = 2;
  return s;
}

inline AtmosphereModel cachedModel(const ModelConfig& config) {
  return loadOrPrecompute(config, testCacheDirectory());
}

// Tiny tables of two scattering orders (seconds, once, through the test cache): at night, with
// the sun far down, the night's own lights and the moon decide, not the tables' resolution.
inline std::shared_ptr<const AtmosphereModel> tinyNightModel() {
  static const auto m = [] {
    ModelConfig c = smallEarthConfig();
    c.sizes = tinySizes();
    c.options.scatteringOrders = 2;
    return std::make_shared<const AtmosphereModel>(cachedModel(c));
  }();
  return m;
}

}  // namespace skyig::atmosphere::testing
