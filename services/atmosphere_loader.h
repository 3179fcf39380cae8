#pragma once
// Loads the physical atmosphere's tables when the configuration asks for the physical sky:
// from the disk cache when a file matches every parameter, else precomputed (and cached) on
// the GPU when an OpenGL 4.5 context can be made, on the CPU otherwise.
#include "sky/atmosphere/conditions.h"
#include "sky/atmosphere/model.h"
#include "sky/atmosphere/table_cache.h"
#include "sky/atmosphere/updater.h"
#include "services/node_config.h"

#include <atomic>
#include <filesystem>
#include <memory>
#include <string>

namespace skyig::services {

// Where tables missing from the cache are computed. kAuto: the GPU precompute in a headless
// EGL context of its own (render/passes/atmosphere_gpu_precompute.h), falling back to the CPU one
// when no context can be made or the GPU path fails; kGpu: the GPU or an error; kCpu: the
// CPU reference (minutes for the default tables).
enum class PrecomputeDevice { kAuto, kGpu, kCpu };

// "auto", "gpu" or "cpu"; throws std::invalid_argument naming anything else.
PrecomputeDevice parsePrecomputeDevice(const std::string& name);
// $SKYIG_ATMOSPHERE_PRECOMPUTE (auto when unset or empty).
PrecomputeDevice precomputeDeviceFromEnvironment();

// The table builder of the loader, for AtmosphereUpdater too. Says on stderr which device it
// used (and why it fell back), a line per group of four wavelengths, and the total time.
// Invalid configurations throw std::invalid_argument whatever the device.
atmosphere::TableBuilder atmosphereTableBuilder(PrecomputeDevice device = precomputeDeviceFromEnvironment());

// Where tables are cached: settings.cacheDir, else $CACHE_DIRECTORY (the directory systemd
// made for the service's CacheDirectory=, /var/cache/skyig; the first of a ':'-separated list),
// else $XDG_CACHE_HOME/skyig or ~/.cache/skyig.
std::filesystem::path cacheDirectory(const AtmosphereSettings& settings);

// The model `settings` describe under `conditions`: table size, scattering orders, and
// settings.medium with the conditions applied. Every caller builds it here, so the loader, the
// node's updater and the probe find the same cache files.
atmosphere::ModelConfig modelConfig(const AtmosphereSettings& settings, const atmosphere::Conditions& conditions);

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

// The background updater the sky worker (services/sky_worker.h) follows the host's visibility
// and humidity with, in `serve` and `replay` alike: its first model is the configuration's
// (from the cache loadAtmosphereIfNeeded filled), later ones are built by
// atmosphereTableBuilder. Null unless the sky is physical. The cache keeps to
// sky.atmosphere_cache_max_mb; with rateLimited (serve) at most one precompute per
// sky.atmosphere_build_interval seconds, and a visibility between two cached steps blended from
// them at once (visibilitySteps; their missing tables built in the background); replay builds every held visibility (it waits for the
// tables and follows the recording's clock, not this machine's). `stop` (the command's signal
// flag) ends its precomputes and waits at once (atmosphere/updater.h).
// The visibility steps of the node (sky.atmosphere_visibility_steps), cached in the folder
// "visibility-steps" of the cache directory, which the cache's size bound does not reach.
atmosphere::VisibilitySteps visibilitySteps(const NodeConfig& config);

std::unique_ptr<atmosphere::AtmosphereUpdater> makeAtmosphereUpdater(const NodeConfig& config, bool rateLimited = true,
                                                                     const std::atomic<bool>* stop = nullptr);

}  // namespace skyig::services
