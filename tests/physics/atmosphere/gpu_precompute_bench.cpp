// Times the GPU precompute of the physical sky's tables (16 wavelengths, 4 orders) at one size,
// on whatever EGL gives (llvmpipe here, a GPU elsewhere): a measurement, not a test (ctest does
// not run it). docs/performance.md quotes its figures.
//   build/tests/physics/atmosphere/atmosphere_gpu_bench [small|medium|default] [--per-pass] [--density-divisor 2]
#include "physics/atmosphere/model.h"
#include "render/passes/precompute/atmosphere_gpu_precompute.h"
#include "render/gl/gl_context.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

using namespace skyig;

int main(int argc, char** argv) {
  std::string size = "default";
  render::GpuPrecomputeOptions options;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--per-pass") == 0) {
      options.time_passes = true;  // a glFinish after every pass
    } else if (std::strcmp(argv[i], "--density-divisor") == 0 && i + 1 < argc) {
      options.density_divisor = std::stoi(argv[++i]);
    } else {
      size = argv[i];
    }
  }
  try {
    atmosphere::ModelConfig config;
    config.sizes = atmosphere::TableSizes::named(size);
    const auto gl = render::createHeadlessContext();
    std::printf("%s, %s tables, %zu wavelengths\n", gl->info().renderer.c_str(), size.c_str(), config.wavelengthsNm.size());
    options.progress = [](const std::string& line) { std::printf("  %s\n", line.c_str()); };
    render::AtmosphereGpuPrecompute precompute;
    render::GpuPrecomputeTiming timing;
    const auto start = std::chrono::steady_clock::now();
    precompute.computeTables(config, options, &timing);
    std::printf("%s\nwall %.2f s\n", render::describe(timing).c_str(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "atmosphere_gpu_bench: %s\n", e.what());
    return 1;
  }
}
