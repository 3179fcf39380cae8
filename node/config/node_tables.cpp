#include "node/config/node_tables.h"

#include "physics/weather/fog_layer.h"

#include <chrono>
#include <cstdio>

namespace skyig::services {

atmosphere::ModelConfig nodeModelConfig(const NodeConfig& config, const atmosphere::Conditions& conditions) {
  atmosphere::Conditions c = conditions;
  if (!c.groundAlbedo) c.groundAlbedo = config.sky.groundAlbedo;
  if (!c.visibilityKm) c.visibilityKm = config.atmosphere.visibilityKm;
  // Below the tables' visibility the rest is a fog layer (physics/weather/fog_layer.h).
  if (c.visibilityKm) c.visibilityKm = weather::tablesVisibilityKm(*c.visibilityKm);
  return modelConfig(config.atmosphere, c);
}

std::shared_ptr<const atmosphere::AtmosphereModel> loadNodeAtmosphere(const NodeConfig& config,
                                                                      const atmosphere::Conditions& conditions,
                                                                      atmosphere::CacheResult* result,
                                                                      const std::atomic<bool>* stop) {
  atmosphere::CacheResult cache;
  const auto start = std::chrono::steady_clock::now();
  auto loaded = std::make_shared<const atmosphere::AtmosphereModel>(
      atmosphere::loadOrPrecompute(nodeModelConfig(config, conditions), cacheDirectory(config.atmosphere), &cache,
                                   atmosphereTableBuilder(), config.atmosphere.cacheMaxBytes,
                                   {atmosphere::CancelToken(stop), {}}));
  if (cache.outcome != atmosphere::CacheOutcome::kLoaded)
    std::fprintf(stderr, "physical sky: precomputed the %s tables in %.1f s (%s); %s %s\n",
                 config.atmosphere.tables.c_str(),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), cache.reason.c_str(),
                 cache.writeError.empty() ? "cached in" : "not cached, running on them:",
                 cache.writeError.empty() ? cache.path.string().c_str() : cache.writeError.c_str());
  if (result) *result = cache;
  return loaded;
}

atmosphere::VisibilitySteps visibilitySteps(const NodeConfig& config) {
  return {config.atmosphere.visibilityStepsKm, cacheDirectory(config.atmosphere) / "visibility-steps"};
}

std::unique_ptr<atmosphere::AtmosphereUpdater> makeAtmosphereUpdater(const NodeConfig& config, bool rateLimited,
                                                                     const std::atomic<bool>* stop) {
  if (config.sky.model != sky::SkyModel::Physical) return nullptr;
  atmosphere::UpdaterLimits limits;
  limits.maxCacheBytes = config.atmosphere.cacheMaxBytes;
  limits.minBuildIntervalS = rateLimited ? config.atmosphere.buildIntervalS : 0.0;
  limits.backgroundPriority = rateLimited;  // serve's frames are real time; a replay waits for its builds
  // serve blends between cached visibility steps while a host's tables are built; replay waits
  // for each visibility's exact tables anyway.
  atmosphere::VisibilitySteps steps;
  if (rateLimited) steps = visibilitySteps(config);
  // The configuration's tables, when the start-up load put them in memory: not loaded again.
  return std::make_unique<atmosphere::AtmosphereUpdater>(nodeModelConfig(config, {}), cacheDirectory(config.atmosphere),
                                                         atmosphereTableBuilder(), limits, stop, std::move(steps),
                                                         config.sky.atmosphere);
}

void loadAtmosphereIfNeeded(NodeConfig& config, const std::atomic<bool>* stop) {
  if (config.sky.model != sky::SkyModel::Physical || config.sky.atmosphere) return;
  config.sky.atmosphere = loadNodeAtmosphere(config, {}, nullptr, stop);
  config.sky.haze = nodeHaze(config, config.atmosphere.visibilityKm.value_or(0.0));
}

sky::FogSpec nodeHaze(const NodeConfig& config, double visibilityKm) {
  // The haze below the tables' 10 km is water whatever the aerosol type: at a visibility that
  // low the particles have grown to droplets (an OPAC type's dry albedo, 0.89 for continental
  // average, would absorb a 400 m fog's many scatterings: its sky came out 16 times too dark).
  return weather::hazeBelowTables(visibilityKm, config.atmosphere.medium.mieScaleHeightM);
}

}  // namespace skyig::services
