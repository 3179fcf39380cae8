#include "tables/loader.h"

#include "tables/background_priority.h"
#include "tables/table_cache.h"
#include "render/passes/precompute/atmosphere_gpu_precompute.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace skyig::services {

namespace {
double since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Says what a precompute is doing: a line as it starts, then the step it is at every few
// seconds (one step of the default tables takes half a minute on llvmpipe, the whole minutes),
// so a first start is never silent.
class PrecomputeReporter {
 public:
  PrecomputeReporter(const atmosphere::ModelConfig& config, const char* device) : device_(device) {
    std::fprintf(stderr,
                 "physical sky: precomputing %zu wavelength groups of tables on the %s (progress every %.0f s)\n",
                 (config.wavelengthsNm.size() + 3) / 4, device, kIntervalS);
    thread_ = std::thread([this] { run(); });
  }
  ~PrecomputeReporter() {
    {
      std::lock_guard lock(mutex_);
      done_ = true;
    }
    wake_.notify_all();
    thread_.join();
  }
  PrecomputeReporter(const PrecomputeReporter&) = delete;
  PrecomputeReporter& operator=(const PrecomputeReporter&) = delete;

  // control with its step reported here.
  atmosphere::PrecomputeControl wrap(const atmosphere::PrecomputeControl& control) {
    return {control.cancel, [this, outer = control.step](const std::string& name) {
              {
                std::lock_guard lock(mutex_);
                step_ = name;
              }
              if (outer) outer(name);
            }};
  }

 private:
  static constexpr double kIntervalS = 3.0;
  void run() {
    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::duration<double>(kIntervalS), [this] { return done_; }))
      std::fprintf(stderr, "physical sky: %s precompute at %s (%.0f s)\n", device_,
                   step_.empty() ? "start" : step_.c_str(), since(start_));
  }

  const char* device_;
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::mutex mutex_;
  std::condition_variable wake_;
  std::string step_;
  bool done_ = false;
  std::thread thread_;
};

std::vector<atmosphere::GroupTables> onGpu(const atmosphere::ModelConfig& config,
                                           const atmosphere::PrecomputeControl& control) {
  const auto start = std::chrono::steady_clock::now();
  PrecomputeReporter reporter(config, "GPU");
  render::GpuPrecomputeOptions options;
  options.progress = [](const std::string& line) { std::fprintf(stderr, "physical sky: GPU precompute %s\n", line.c_str()); };
  options.control = reporter.wrap(control);
  // A build on a lowered thread (the updater's, for the host's air) gets a software device's
  // threads lowered the same way; the initial model, built before the first frame, keeps the
  // caller's priority and the renderer's display (lowered, a loaded machine could starve it).
  if (atmosphere::thisThreadNice() >= atmosphere::kBackgroundNice)
    options.display_threads = [] { atmosphere::lowerThisThreadToBackground(); };
  auto tables = render::precomputeTablesOnGpu(config, options);
  std::fprintf(stderr, "physical sky: precomputed %zu wavelength groups on the GPU in %.1f s\n", tables.size(), since(start));
  return tables;
}

std::vector<atmosphere::GroupTables> onCpu(const atmosphere::ModelConfig& config,
                                           const atmosphere::PrecomputeControl& control) {
  const auto start = std::chrono::steady_clock::now();
  if (config.wavelengthsNm.empty()) throw std::invalid_argument("atmosphere precompute: no wavelengths");
  PrecomputeReporter reporter(config, "CPU");
  auto tables = atmosphere::precomputeTablesOnCpu(config, reporter.wrap(control));
  std::fprintf(stderr, "physical sky: precomputed %zu wavelength groups on the CPU in %.1f s\n", tables.size(),
               since(start));
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
  return [device](const atmosphere::ModelConfig& config, const atmosphere::PrecomputeControl& control) {
    (void)atmosphere::SpectralConverter(config.wavelengthsNm);  // bad wavelengths throw before any work
    if (device == PrecomputeDevice::kCpu) return onCpu(config, control);
    if (device == PrecomputeDevice::kGpu) return onGpu(config, control);
    try {
      return onGpu(config, control);
    } catch (const std::invalid_argument&) {
      throw;  // the CPU would refuse the config too
    } catch (const atmosphere::Cancelled&) {
      throw;  // asked to stop, not a GPU failure
    } catch (const std::exception& e) {
      std::fprintf(stderr, "physical sky: no GPU precompute (%s); computing on the CPU\n", e.what());
    }
    return onCpu(config, control);
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

}  // namespace skyig::services
