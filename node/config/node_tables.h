#pragma once
// The node's tables: the model its configuration asks for, loaded from the cache or built
// (tables/loader.h), and the background updater that follows the host's air with it. Every
// command that draws or probes the physical sky reaches its tables through here, so one
// configuration is one cache file.
#include "physics/atmosphere/conditions.h"
#include "physics/atmosphere/model.h"
#include "node/config/node_config.h"
#include "tables/loader.h"
#include "tables/table_cache.h"
#include "tables/updater.h"

#include <atomic>
#include <memory>

namespace skyig::services {

// The model config the node uses for the host's `conditions`: the configuration's (its ground
// albedo unless the host gives one), built by tables/loader.h's modelConfig, so the
// tables come from the same cache files as the start-up load.
atmosphere::ModelConfig nodeModelConfig(const NodeConfig& config, const atmosphere::Conditions& conditions);

// The node's model (nodeModelConfig: sky.ground_albedo and [atmosphere] visibility_km unless
// `conditions` say otherwise) from its cache directory, or precomputed (atmosphereTableBuilder)
// and cached there; says on stderr when it has to precompute. `render`, `serve`, `replay` and
// `probe` all load through here, so one configuration is one cache file and one ground albedo.
// `result`, when given, says whether the tables were loaded or precomputed. Once `stop` is set
// (a signalled command) a precompute ends within a slice: atmosphere::Cancelled.
std::shared_ptr<const atmosphere::AtmosphereModel> loadNodeAtmosphere(const NodeConfig& config,
                                                                      const atmosphere::Conditions& conditions = {},
                                                                      atmosphere::CacheResult* result = nullptr,
                                                                      const std::atomic<bool>* stop = nullptr);

// Sets config.sky.atmosphere when config.sky.model is physical; prints to stderr when it has
// to precompute; `stop` as loadNodeAtmosphere.
void loadAtmosphereIfNeeded(NodeConfig& config, const std::atomic<bool>* stop = nullptr);

// What a visibility below the tables' leaves to the haze layer over the configured medium
// (physics/weather/fog_layer.h; nodeModelConfig builds the tables at the rest): the node's
// visibility from the configuration (loadAtmosphereIfNeeded) or from the host (SkyWorker).
sky::FogSpec nodeHaze(const NodeConfig& config, double visibilityKm);

// The visibility steps of the node (sky.atmosphere_visibility_steps), cached in the folder
// "visibility-steps" of the cache directory, which the cache's size bound does not reach.
atmosphere::VisibilitySteps visibilitySteps(const NodeConfig& config);

// The background updater the sky worker (node/frame/sky_worker.h) follows the host's visibility
// and humidity with, in `serve` and `replay` alike: its first model is the configuration's
// (from the cache loadAtmosphereIfNeeded filled), later ones are built by
// atmosphereTableBuilder. Null unless the sky is physical. The cache keeps to
// sky.atmosphere_cache_max_mb; with rateLimited (serve) at most one precompute per
// sky.atmosphere_build_interval seconds, and a visibility between two cached steps blended from
// them at once (visibilitySteps; their missing tables built in the background); replay builds
// every held visibility (it waits for the tables and follows the recording's clock, not this
// machine's). `stop` (the command's signal flag) ends its precomputes and waits at once
// (tables/updater.h).
std::unique_ptr<atmosphere::AtmosphereUpdater> makeAtmosphereUpdater(const NodeConfig& config, bool rateLimited = true,
                                                                     const std::atomic<bool>* stop = nullptr);

}  // namespace skyig::services
