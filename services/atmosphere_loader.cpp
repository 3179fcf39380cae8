#include "services/atmosphere_loader.h"

#include "services/host_atmosphere.h"

#include "sky/atmosphere/table_cache.h"
#include "render/passes/atmosphere_gpu_precompute.h"

#include <chrono>
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace skyig::services {

namespace {
double since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::vector<atmosphere::GroupTables> onGpu(const atmosphere::ModelConfig& config) {
  const auto start = std::chrono::steady_clock::now();
  render::GpuPrecomputeOptions options;
  options.progress = [](const std::string& line) { std::fprintf(stderr, "physical sky: GPU precompute %s\n", line.c_str()); };
  auto tables = render::precomputeTablesOnGpu(config, options);
  std::fprintf(stderr, "physical sky: precomputed %zu wavelength groups on the GPU in %.1f s\n", tables.size(), since(start));
  return tables;
}

std::vector<atmosphere::GroupTables> onCpu(const atmosphere::ModelConfig& config) {
  const auto start = std::chrono::steady_clock::now();
  // The CPU path has no per-group progress of its own: the groups one by one give it.
  if (config.wavelengthsNm.empty()) throw std::invalid_argument("atmosphere precompute: no wavelengths");
  std::vector<atmosphere::GroupTables> tables;
  const std::size_t groups = (config.wavelengthsNm.size() + 3) / 4;
  for (std::size_t g = 0; g < groups; ++g) {
    const auto group_start = std::chrono::steady_clock::now();
    // As AtmosphereModel: the last group padded by repeating the last wavelength.
    std::array<double, 4> wavelengths{};
    for (std::size_t i = 0; i < 4; ++i)
      wavelengths[i] = config.wavelengthsNm[std::min(g * 4 + i, config.wavelengthsNm.size() - 1)];
    tables.push_back(atmosphere::precomputeGroup(atmosphere::makeParameters(config.medium, wavelengths, config.sizes),
                                                 config.options));
    std::fprintf(stderr, "physical sky: CPU precompute group %zu/%zu done (%.1f s)\n", g + 1, groups, since(group_start));
  }
  std::fprintf(stderr, "physical sky: precomputed %zu wavelength groups on the CPU in %.1f s\n", groups, since(start));
  return tables;
}

}  // namespace

PrecomputeDevice parsePrecomputeDevice(const std::string& name) {
  if (name == "auto") return PrecomputeDevice::kAuto;
  if (name == "gpu") return PrecomputeDevice::kGpu;
  if (name == "cpu") return PrecomputeDevice::kCpu;
  throw std::invalid_argument("atmosphere precompute device \"" + name + "\" is invalid (expected auto, gpu or cpu)");
}

PrecomputeDevice precomputeDeviceFromEnvironment() {
  const char* value = std::getenv("SKYIG_ATMOSPHERE_PRECOMPUTE");
  return value && *value ? parsePrecomputeDevice(value) : PrecomputeDevice::kAuto;
}

atmosphere::TableBuilder atmosphereTableBuilder(PrecomputeDevice device) {
  return [device](const atmosphere::ModelConfig& config) {
    (void)atmosphere::SpectralConverter(config.wavelengthsNm);  // bad wavelengths throw before any work
    if (device == PrecomputeDevice::kCpu) return onCpu(config);
    if (device == PrecomputeDevice::kGpu) return onGpu(config);
    try {
      return onGpu(config);
    } catch (const std::invalid_argument&) {
      throw;  // the CPU would refuse the config too
    } catch (const std::exception& e) {
      std::fprintf(stderr, "physical sky: no GPU precompute (%s); computing on the CPU\n", e.what());
    }
    return onCpu(config);
  };
}

std::filesystem::path cacheDirectory(const AtmosphereSettings& settings) {
  if (!settings.cacheDir.empty()) return settings.cacheDir;
  if (const char* service = std::getenv("CACHE_DIRECTORY"); service && *service && *service != ':')
    return std::string(service).substr(0, std::string(service).find(':'));
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "skyig";
  if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache" / "skyig";
  return std::filesystem::temp_directory_path() / "skyig-cache";
}

atmosphere::ModelConfig modelConfig(const AtmosphereSettings& settings, const atmosphere::Conditions& conditions) {
  atmosphere::ModelConfig model;
  model.sizes = atmosphere::TableSizes::named(settings.tables);
  model.options.scatteringOrders = settings.scatteringOrders;
  model.medium = atmosphere::applyConditions(settings.medium, conditions);
  return model;
}

std::shared_ptr<const atmosphere::AtmosphereModel> loadNodeAtmosphere(const NodeConfig& config,
                                                                      const atmosphere::Conditions& conditions,
                                                                      atmosphere::CacheResult* result) {
  atmosphere::CacheResult cache;
  const auto start = std::chrono::steady_clock::now();
  auto loaded = std::make_shared<const atmosphere::AtmosphereModel>(
      atmosphere::loadOrPrecompute(nodeModelConfig(config, conditions), cacheDirectory(config.atmosphere), &cache,
                                   atmosphereTableBuilder(), config.atmosphere.cacheMaxBytes));
  if (cache.outcome != atmosphere::CacheOutcome::kLoaded)
    std::fprintf(stderr, "physical sky: precomputed the %s tables in %.1f s (%s); cached in %s\n",
                 config.atmosphere.tables.c_str(),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), cache.reason.c_str(),
                 cache.path.string().c_str());
  if (result) *result = cache;
  return loaded;
}

std::unique_ptr<atmosphere::AtmosphereUpdater> makeAtmosphereUpdater(const NodeConfig& config, bool rateLimited) {
  if (config.sky.model != sky::SkyModel::Physical) return nullptr;
  atmosphere::UpdaterLimits limits;
  limits.maxCacheBytes = config.atmosphere.cacheMaxBytes;
  limits.minBuildIntervalS = rateLimited ? config.atmosphere.buildIntervalS : 0.0;
  return std::make_unique<atmosphere::AtmosphereUpdater>(nodeModelConfig(config, {}), cacheDirectory(config.atmosphere),
                                                         atmosphereTableBuilder(), limits);
}

void loadAtmosphereIfNeeded(NodeConfig& config) {
  if (config.sky.model != sky::SkyModel::Physical || config.sky.atmosphere) return;
  config.sky.atmosphere = loadNodeAtmosphere(config);
}

}  // namespace skyig::services
