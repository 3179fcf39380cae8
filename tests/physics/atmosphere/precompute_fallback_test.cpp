// Which precompute tables/loader.h uses: the GPU when an OpenGL 4.5 context can be
// made, the CPU otherwise (said on stderr), and the same builder driving AtmosphereUpdater
// from its own thread. The case without GL runs this binary again in an environment where
// EGL finds no driver (glvnd reads __EGL_VENDOR_LIBRARY_FILENAMES when EGL first loads).
#include <gtest/gtest.h>

#include <EGL/egl.h>

#include <array>
#include <atomic>
#include <chrono>
#include <thread>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <vector>
#include <memory>
#include <string>

#include "tables/background_priority.h"
#include "tables/updater.h"
#include "render/passes/precompute/atmosphere_gpu_precompute.h"
#include "render/gl/gl_context.h"
#include "tables/loader.h"
#include "shared_models.h"

namespace skyig::services {
namespace {

using atmosphere::GroupTables;
using atmosphere::ModelConfig;

ModelConfig tinyConfig() {
  ModelConfig c = atmosphere::testing::oneGroupConfig();
  c.sizes = atmosphere::testing::tinySizes();
  c.options.scatteringOrders = 2;
  return c;
}

bool sameTables(const std::vector<GroupTables>& a, const std::vector<GroupTables>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t g = 0; g < a.size(); ++g) {
    if (a[g].transmittance.texels != b[g].transmittance.texels || a[g].irradiance.texels != b[g].irradiance.texels ||
        a[g].scattering.texels != b[g].scattering.texels || a[g].singleMie.texels != b[g].singleMie.texels)
      return false;
  }
  return true;
}

bool glAvailable() {
  try {
    render::createHeadlessContext();
    return true;
  } catch (const render::GlContextError&) {
    return false;
  }
}

TEST(AtmospherePrecomputeDevice, NamesParseAndBadOnesAreRejected) {
  EXPECT_EQ(parsePrecomputeDevice("auto"), PrecomputeDevice::kAuto);
  EXPECT_EQ(parsePrecomputeDevice("gpu"), PrecomputeDevice::kGpu);
  EXPECT_EQ(parsePrecomputeDevice("cpu"), PrecomputeDevice::kCpu);
  try {
    parsePrecomputeDevice("metal");
    FAIL() << "accepted \"metal\"";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("metal"), std::string::npos) << e.what();
  }
}

TEST(AtmospherePrecomputeDevice, CpuBuilderGivesTheCpuReferenceAndSaysSo) {
  const ModelConfig c = tinyConfig();
  ::testing::internal::CaptureStderr();
  const auto tables = atmosphereTableBuilder(PrecomputeDevice::kCpu)(c, {});
  const std::string said = ::testing::internal::GetCapturedStderr();
  EXPECT_TRUE(sameTables(tables, atmosphere::precomputeTablesOnCpu(c)));
  EXPECT_NE(said.find("on the CPU in"), std::string::npos) << said;
}

TEST(AtmospherePrecomputeDevice, AutoUsesTheGpuWhenAContextCanBeMade) {
  if (!glAvailable()) GTEST_SKIP() << "no OpenGL 4.5 context through EGL";
  const ModelConfig c = tinyConfig();
  ::testing::internal::CaptureStderr();
  const auto tables = atmosphereTableBuilder(PrecomputeDevice::kAuto)(c, {});
  const std::string said = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(said.find("on the GPU in"), std::string::npos) << said;
  EXPECT_TRUE(sameTables(tables, render::precomputeTablesOnGpu(c)));
  EXPECT_FALSE(sameTables(tables, atmosphere::precomputeTablesOnCpu(c)));  // float, not double
}

TEST(AtmospherePrecomputeDevice, InvalidConfigsThrowWhateverTheDevice) {
  ModelConfig c = tinyConfig();
  c.medium.miePhaseG = 1.5;
  for (PrecomputeDevice d : {PrecomputeDevice::kAuto, PrecomputeDevice::kCpu}) {
    EXPECT_THROW(atmosphereTableBuilder(d)(c, {}), std::invalid_argument);
  }
  c = tinyConfig();
  c.wavelengthsNm = {550.0, 440.0};
  EXPECT_THROW(atmosphereTableBuilder(PrecomputeDevice::kAuto)(c, {}), std::invalid_argument);
}

// Runs in the child process of the next test, where EGL has no driver.
TEST(AtmospherePrecomputeDevice, WithoutGlChild) {
  if (!std::getenv("SKYIG_PRECOMPUTE_FALLBACK_CHILD")) GTEST_SKIP() << "run by AutoFallsBackToTheCpuWithoutGl";
  ASSERT_FALSE(glAvailable());
  const ModelConfig c = tinyConfig();
  EXPECT_TRUE(sameTables(atmosphereTableBuilder(PrecomputeDevice::kAuto)(c, {}), atmosphere::precomputeTablesOnCpu(c)));
  EXPECT_THROW(atmosphereTableBuilder(PrecomputeDevice::kGpu)(c, {}), render::GlContextError);
}

TEST(AtmospherePrecomputeDevice, AutoFallsBackToTheCpuWithoutGl) {
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  const std::string command = "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent/egl_vendor.json "
                              "SKYIG_PRECOMPUTE_FALLBACK_CHILD=1 '" + self +
                              "' --gtest_filter=AtmospherePrecomputeDevice.WithoutGlChild 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string output;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe)) output += buffer.data();
  const int status = pclose(pipe);
  EXPECT_EQ(status, 0) << output;
  EXPECT_NE(output.find("[  PASSED  ] 1 test"), std::string::npos) << output;
  EXPECT_NE(output.find("no GPU precompute ("), std::string::npos) << output;
  EXPECT_NE(output.find("on the CPU in"), std::string::npos) << output;
}

// The updater with the loader's builder: tables computed on its own thread in a context of
// its own, while this thread's context stays current.
TEST(AtmospherePrecomputeDevice, UpdaterBuildsOnTheGpuFromItsThread) {
  std::unique_ptr<render::GlContext> mine;
  try {
    mine = render::createHeadlessContext();
  } catch (const render::GlContextError&) {
    GTEST_SKIP() << "no OpenGL 4.5 context through EGL";
  }
  const EGLContext current = eglGetCurrentContext();
  const auto dir = std::filesystem::path(SKYIG_BINARY_DIR) / "atmosphere-test-cache" / "gpu-updater";
  std::filesystem::remove_all(dir);
  ModelConfig c = tinyConfig();
  ::testing::internal::CaptureStderr();
  atmosphere::AtmosphereUpdater updater(c, dir, atmosphereTableBuilder(PrecomputeDevice::kGpu));
  EXPECT_EQ(eglGetCurrentContext(), current);
  c.medium.groundAlbedo = 0.3;
  updater.request(c);
  updater.waitIdle();
  const std::string said = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(updater.lastError(), "");
  EXPECT_EQ(updater.generation(), 1u);
  EXPECT_NE(said.find("on the GPU in"), std::string::npos) << said;
  const auto model = updater.current();
  std::vector<GroupTables> expected = render::precomputeTablesOnGpu(c);
  atmosphere::roundTablesToFloat(expected);
  EXPECT_TRUE(sameTables({model->tables(0)}, expected));
  EXPECT_EQ(eglGetCurrentContext(), current);
}

// One thread's CPU time (clock ticks) and nice value (proc(5), /proc/PID/stat fields 14, 15 and
// 19, counted after the command name's closing parenthesis).
struct ThreadCpu {
  long ticks = 0;
  int nice = 0;
};

std::map<std::string, ThreadCpu> threadsOfThisProcess() {
  std::map<std::string, ThreadCpu> threads;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task")) {
    std::ifstream in(task.path() / "stat");
    std::string line;
    if (!std::getline(in, line) || line.rfind(')') == std::string::npos) continue;
    std::istringstream fields(line.substr(line.rfind(')') + 2));
    std::vector<std::string> f{std::istream_iterator<std::string>(fields), {}};
    if (f.size() < 17) continue;
    threads[task.path().filename().string()] = {std::stol(f[11]) + std::stol(f[12]), std::stoi(f[16])};
  }
  return threads;
}

// On llvmpipe a display's draws and compute dispatches run on threads the display owns. A table
// build the host asked for, beside a renderer's context on the same software device, runs on
// threads at the build's background priority (nice 19), not on the renderer's at its priority:
// a display of the build's own whose threads start from a lowered thread. The initial model,
// built first on this thread, is not lowered.
TEST(AtmospherePrecomputeDevice, BesideASoftwareRendererABuildRunsOnThreadsAtItsOwnPriority) {
  std::unique_ptr<render::GlContext> renderer;
  try {
    renderer = render::createHeadlessContext();
  } catch (const render::GlContextError&) {
    GTEST_SKIP() << "no OpenGL 4.5 context through EGL";
  }
  if (renderer->info().renderer.find("llvmpipe") == std::string::npos)
    GTEST_SKIP() << "a hardware renderer (" << renderer->info().renderer << "): the GPU does the build";
  if (atmosphere::thisThreadNice() >= atmosphere::kBackgroundNice) GTEST_SKIP() << "run at the background priority already";
  const auto dir = std::filesystem::path(SKYIG_BINARY_DIR) / "atmosphere-test-cache" / "gpu-build-priority";
  std::filesystem::remove_all(dir);
  ModelConfig c = atmosphere::testing::oneGroupConfig();
  ::testing::internal::CaptureStderr();
  atmosphere::AtmosphereUpdater updater(c, dir, atmosphereTableBuilder(PrecomputeDevice::kGpu));
  c.medium.groundAlbedo = 0.3;
  const auto before = threadsOfThisProcess();
  updater.request(c);
  updater.waitIdle();
  const auto after = threadsOfThisProcess();
  const std::string said = ::testing::internal::GetCapturedStderr();
  ASSERT_EQ(updater.generation(), 1u) << said;
  long all = 0, atNormalPriority = 0;
  std::string normal;
  for (const auto& [tid, now] : after) {
    const auto was = before.find(tid);
    const long grown = now.ticks - (was == before.end() ? 0 : was->second.ticks);
    all += grown;
    if (now.nice < atmosphere::kBackgroundNice) {
      atNormalPriority += grown;
      if (grown > 0) normal += " " + tid + " (nice " + std::to_string(now.nice) + "): " + std::to_string(grown) + " ticks;";
    }
  }
  ASSERT_GE(all, 10) << "the build used too little CPU to tell (" << all << " ticks)";
  EXPECT_LE(atNormalPriority, all / 20) << "of " << all << " ticks, at normal priority:" << normal;
}

// A cancelled GPU precompute stops within a radius slice of its pass: at the medium sizes the
// scattering density pass alone takes ~10 s of llvmpipe, one of its 32 slices a third of one.
TEST(AtmospherePrecomputeDevice, GpuPrecomputeStopsWithinASliceOfItsPass) {
  if (!glAvailable()) GTEST_SKIP() << "no OpenGL 4.5 context through EGL";
  ModelConfig c = atmosphere::testing::oneGroupConfig();
  c.sizes = atmosphere::TableSizes::named("medium");
  std::atomic<bool> cancel{false};
  std::atomic<bool> inDensity{false};
  render::GpuPrecomputeOptions options;
  options.control.cancel = atmosphere::CancelToken(&cancel);
  options.control.step = [&](const std::string& step) {
    if (step.find("scattering density") != std::string::npos) inDensity = true;
  };
  std::atomic<bool> cancelled{false};
  std::thread worker([&] {
    try {
      render::precomputeTablesOnGpu(c, options);
    } catch (const atmosphere::Cancelled&) {
      cancelled = true;
    }
  });
  const auto start = std::chrono::steady_clock::now();
  while (!inDensity && std::chrono::steady_clock::now() - start < std::chrono::seconds(120))
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_TRUE(inDensity.load());
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // into the pass
  const auto asked = std::chrono::steady_clock::now();
  cancel = true;
  worker.join();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - asked).count();
  EXPECT_TRUE(cancelled.load());
  EXPECT_LT(seconds, 2.0);
}

// The loader's builder reports progress from its start and then every few seconds, and a
// cancelled build writes no cache file.
TEST(AtmospherePrecomputeDevice, LoaderSaysWhereItIsAndACancelledBuildCachesNothing) {
  if (!glAvailable()) GTEST_SKIP() << "no OpenGL 4.5 context through EGL";
  // Bruneton's sizes: one group takes ~20 s of llvmpipe, well past the cancellation at 4.5 s (the
  // medium ones now build in less).
  ModelConfig c = atmosphere::testing::oneGroupConfig();
  c.sizes = atmosphere::TableSizes::named("default");
  const auto dir = std::filesystem::path(SKYIG_BINARY_DIR) / "atmosphere-test-cache" / "cancelled-build";
  std::filesystem::remove_all(dir);
  std::atomic<bool> cancel{false};
  ::testing::internal::CaptureStderr();
  std::thread stopper([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(4500));
    cancel = true;
  });
  EXPECT_THROW(atmosphere::loadOrPrecompute(c, dir, nullptr, atmosphereTableBuilder(PrecomputeDevice::kGpu),
                                            0, {atmosphere::CancelToken(&cancel), {}}),
               atmosphere::Cancelled);
  stopper.join();
  const std::string said = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(said.find("physical sky: precomputing 1 wavelength groups"), 0u) << said;
  EXPECT_NE(said.find("GPU precompute at group 1/1: "), std::string::npos) << said;  // after 3 s
  EXPECT_FALSE(std::filesystem::exists(atmosphere::cacheFilePath(dir, c)));
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(entry.path().extension(), ".lock") << entry.path();  // no temporary left either
}

}  // namespace
}  // namespace skyig::services
