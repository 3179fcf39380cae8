#include "commands/precompute_command.h"

#include "node/host/host_atmosphere.h"
#include "node/config/node_tables.h"
#include "node/config/node_config.h"
#include "node/common/stop_signal.h"
#include "physics/atmosphere/conditions.h"

#include <cstdio>
#include <memory>
#include <string>

namespace skyig::services {

namespace {

struct PrecomputeCli {
  std::string configPath;
  std::string cacheDir;
};

int run(const PrecomputeCli& cli) {
  NodeConfig config = cli.configPath.empty() ? NodeConfig{} : loadNodeConfig(cli.configPath);
  if (!cli.cacheDir.empty()) config.atmosphere.cacheDir = cli.cacheDir;
  if (config.sky.model != sky::SkyModel::Physical) {
    std::printf("the sky is not the physical one: no tables to precompute\n");
    return 0;
  }
  StopOnSignal signal;
  // The updater serve uses, without its rate limit: the configuration's tables, then each step.
  atmosphere::UpdaterLimits limits;
  limits.maxCacheBytes = config.atmosphere.cacheMaxBytes;
  limits.backgroundPriority = false;  // no frames to keep: the steps at full speed
  atmosphere::AtmosphereUpdater updater(nodeModelConfig(config, {}), cacheDirectory(config.atmosphere),
                                        atmosphereTableBuilder(), limits, &signal.flag(), visibilitySteps(config));
  updater.waitSteps();
  if (signal.requested()) return 0;
  const atmosphere::VisibilitySteps steps = visibilitySteps(config);
  std::printf("%s tables: %.3g km (the configuration's) in %s\n", config.atmosphere.tables.c_str(),
              atmosphere::visibilityOf(updater.current()->config().medium), cacheDirectory(config.atmosphere).string().c_str());
  for (const double km : steps.km)
    std::printf("%s tables: %.3g km (a visibility step) in %s\n", config.atmosphere.tables.c_str(), km,
                steps.directory.string().c_str());
  std::printf("%llu steps built, %llu failed\n", static_cast<unsigned long long>(updater.stepBuilds()),
              static_cast<unsigned long long>(updater.stepFailures()));
  // Its output is the cache: tables that could not be written there are an output that failed.
  if (updater.cacheWriteFailures() > 0)
    std::fprintf(stderr, "skyig precompute: %llu table file(s) could not be written to %s (full or read-only?)\n",
                 static_cast<unsigned long long>(updater.cacheWriteFailures()),
                 cacheDirectory(config.atmosphere).string().c_str());
  return updater.stepFailures() > 0 || updater.cacheWriteFailures() > 0 ? 3 : 0;
}

}  // namespace

void registerPrecomputeCommand(CLI::App& app, int& exitCode) {
  auto cli = std::make_shared<PrecomputeCli>();
  CLI::App* c = app.add_subcommand(
      "precompute", "Build the physical sky's tables of a configuration and its visibility steps into the cache (what serve builds after its first start)");
  c->add_option("--config", cli->configPath, "Node configuration (TOML): its [atmosphere], table size and atmosphere_visibility_steps")
      ->check(CLI::ExistingFile);
  c->add_option("--cache", cli->cacheDir, "Table cache directory (default: the configuration's, else $CACHE_DIRECTORY, $XDG_CACHE_HOME/skyig or ~/.cache/skyig)");
  c->callback([cli, &exitCode] { exitCode = run(*cli); });
}

}  // namespace skyig::services
