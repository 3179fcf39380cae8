#pragma once
// Where the physical atmosphere's tables come from: the disk cache's directory, the model a
// configuration's settings describe, and the builder that precomputes what the cache lacks, on
// the GPU when an OpenGL 4.5 context can be made, on the CPU otherwise. What a node loads with
// them is node/config/node_tables.h.
#include "physics/atmosphere/conditions.h"
#include "physics/atmosphere/model.h"
#include "tables/table_cache.h"
#include "tables/updater.h"
#include "tables/settings.h"

#include <atomic>
#include <filesystem>
#include <memory>
#include <string>

namespace skyig::services {

// Where tables missing from the cache are computed. kAuto: the GPU precompute in a headless
// EGL context of its own (render/passes/precompute/atmosphere_gpu_precompute.h), falling back
// to the CPU one when no context can be made or the GPU path fails; kGpu: the GPU or an error;
// kCpu: the CPU reference (minutes for the default tables).
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

}  // namespace skyig::services
