#pragma once
// The precomputation of the physical atmosphere on the GPU (Bruneton & Neyret 2008, algorithm
// 4.1) with the compute passes of render/passes/precompute/precompute_*.comp: the same steps as the
// CPU reference (physics/atmosphere/precompute/precompute.cpp), in float, for every group of four
// wavelengths of a ModelConfig. The tables are read back into GroupTables, so the result is an
// ordinary AtmosphereModel (cache, probe and renderer take it unchanged).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "physics/atmosphere/model.h"
#include "physics/atmosphere/precompute/precompute_control.h"

namespace skyig::render {

// Wall-clock seconds per pass, summed over the groups and orders (measured after glFinish
// when GpuPrecomputeOptions::time_passes is set; otherwise only total and readback).
struct GpuPrecomputeTiming {
  double compile = 0.0;  // building the six programs (first use of each on llvmpipe)
  double transmittance = 0.0;
  double direct_irradiance = 0.0;
  double single_scattering = 0.0;
  double nu_slices = 0.0;
  double scattering_density = 0.0;
  double indirect_irradiance = 0.0;
  double multiple_scattering = 0.0;
  double readback = 0.0;
  double total = 0.0;  // everything, compile included
};

// "total 3.61 s = compile 0.02, T 0.001, ..." for benchmarks and test logs.
std::string describe(const GpuPrecomputeTiming& t);

struct GpuPrecomputeOptions {
  bool time_passes = false;  // glFinish after every pass to time it (slightly slower)
  // 1: the scattering density J at the tables' size (the CPU reference's quadrature). 2: at
  // half their view zenith angles (mu), half the work of its pass, the costliest, for a
  // difference of ~1% (docs/atmosphere.md); the other tables keep their size. Not the radii:
  // J follows the air and aerosol density profiles, which linear interpolation between half
  // the radii misses by tens of percent.
  int density_divisor = 1;
  // Called after each group with a line such as "group 2/4 done (3.1 s)".
  std::function<void(const std::string&)> progress;
  // Stops the precompute between passes and between the radius slices of a 3D pass (Cancelled),
  // and hears each pass start as "group 2/4: scattering density, order 3/4".
  atmosphere::PrecomputeControl control;
  // precomputeTablesOnGpu: how the threads of a software device's own display are set up
  // (createWorkerHeadlessContext); the node lowers them to the build's background priority.
  std::function<void()> display_threads;
};

class AtmosphereGpuPrecompute {
 public:
  // Needs a current OpenGL 4.5 context; compiles the passes (throws ShaderCompileError).
  AtmosphereGpuPrecompute();
  ~AtmosphereGpuPrecompute();
  AtmosphereGpuPrecompute(const AtmosphereGpuPrecompute&) = delete;
  AtmosphereGpuPrecompute& operator=(const AtmosphereGpuPrecompute&) = delete;

  // The tables of every group of the config (throws std::invalid_argument on a bad config).
  std::vector<atmosphere::GroupTables> computeTables(const atmosphere::ModelConfig& config,
                                                     const GpuPrecomputeOptions& options = {},
                                                     GpuPrecomputeTiming* timing = nullptr);
  atmosphere::AtmosphereModel compute(const atmosphere::ModelConfig& config,
                                      const GpuPrecomputeOptions& options = {},
                                      GpuPrecomputeTiming* timing = nullptr);

 private:
  struct Programs;
  class Run;
  std::unique_ptr<Programs> programs_;
  double compile_seconds_ = 0.0;
};

// The tables computed in a headless EGL context of its own (createWorkerHeadlessContext), for
// a thread without GL or one whose context must not be disturbed (it is current again after).
// Throws GlContextError when no OpenGL 4.5 context can be made.
std::vector<atmosphere::GroupTables> precomputeTablesOnGpu(const atmosphere::ModelConfig& config,
                                                           const GpuPrecomputeOptions& options = {},
                                                           GpuPrecomputeTiming* timing = nullptr);

}  // namespace skyig::render
