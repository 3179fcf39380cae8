#include "services/atmosphere_loader.h"

#include "render/atmosphere/table_cache.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace skyig::services {

namespace {
std::filesystem::path cacheDirectory(const std::string& configured) {
  if (!configured.empty()) return configured;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "skyig";
  if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache" / "skyig";
  return std::filesystem::temp_directory_path() / "skyig-cache";
}
}  // namespace

std::shared_ptr<const atmosphere::AtmosphereModel> loadAtmosphere(const AtmosphereSettings& settings,
                                                                  const atmosphere::Conditions& conditions, int orders) {
  atmosphere::ModelConfig model;
  if (settings.tables == "small") model.sizes = atmosphere::TableSizes::small();
  model.options.scattering_orders = orders;
  model.medium = atmosphere::applyConditions(model.medium, conditions);
  atmosphere::CacheResult cache;
  const auto start = std::chrono::steady_clock::now();
  auto loaded = std::make_shared<const atmosphere::AtmosphereModel>(
      atmosphere::loadOrPrecompute(model, cacheDirectory(settings.cacheDir), &cache));
  if (cache.outcome != atmosphere::CacheOutcome::kLoaded)
    std::fprintf(stderr, "physical sky: precomputed the %s tables in %.1f s (%s); cached in %s\n", settings.tables.c_str(),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), cache.reason.c_str(),
                 cache.path.string().c_str());
  return loaded;
}

void loadAtmosphereIfNeeded(NodeConfig& config) {
  if (config.sky.model != render::SkyModel::Physical || config.sky.atmosphere) return;
  atmosphere::Conditions conditions;
  conditions.ground_albedo = config.sky.groundAlbedo;
  config.sky.atmosphere = loadAtmosphere(config.atmosphere, conditions);
}

}  // namespace skyig::services
