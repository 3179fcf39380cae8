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

void loadAtmosphereIfNeeded(NodeConfig& config) {
  if (config.sky.model != render::SkyModel::Physical || config.sky.atmosphere) return;
  atmosphere::ModelConfig model;
  if (config.atmosphere.tables == "small") model.sizes = atmosphere::TableSizes::small();
  atmosphere::Conditions conditions;
  conditions.ground_albedo = config.sky.groundAlbedo;
  model.medium = atmosphere::applyConditions(model.medium, conditions);
  atmosphere::CacheResult cache;
  const auto start = std::chrono::steady_clock::now();
  config.sky.atmosphere = std::make_shared<const atmosphere::AtmosphereModel>(
      atmosphere::loadOrPrecompute(model, cacheDirectory(config.atmosphere.cacheDir), &cache));
  if (cache.outcome != atmosphere::CacheOutcome::kLoaded)
    std::fprintf(stderr, "physical sky: precomputed the %s tables in %.1f s (%s); cached in %s\n",
                 config.atmosphere.tables.c_str(),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), cache.reason.c_str(),
                 cache.path.string().c_str());
}

}  // namespace skyig::services
