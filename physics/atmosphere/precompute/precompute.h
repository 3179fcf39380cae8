#pragma once
// CPU precomputation of the tables (Bruneton & Neyret 2008, algorithm 4.1) in double
// precision, calling the GLSL physics compiled as C++ (physics/atmosphere/atmosphere_physics.h): the
// reference path, and what skyig uses where there is no GPU precompute. Deterministic: every
// texel is a pure function of the tables of the previous step, whatever the thread count.
#include <array>
#include <functional>

#include "physics/atmosphere/medium.h"
#include "physics/atmosphere/precompute/precompute_control.h"
#include "physics/atmosphere/precompute/tables.h"
#include "physics/atmosphere/atmosphere_physics.h"

namespace skyig::atmosphere {

using shader::atmosphere_types::AtmosphereParameters;

struct PrecomputeOptions {
  int scatteringOrders = 4;  // 1 = single scattering only
  // The orders after the last as a geometric series of its ratio to the one before
  // (orders_tail.h); from 3 orders on.
  bool ordersTail = true;
  int threads = 0;            // 0: one per hardware thread
};

// The shader-side parameters of four wavelengths (nm) of the medium with tables of `sizes`.
AtmosphereParameters makeParameters(const Medium& medium, const std::array<double, 4>& wavelengthsNm,
                                    const TableSizes& sizes);

// Runs fn(i) for i in [0, count) on `threads` threads (0 = hardware), rethrowing the first
// exception.
void parallelFor(int count, int threads, const std::function<void(int)>& fn);

// One group's tables; `control` can stop it (Cancelled) between rows and hears each pass start.
GroupTables precomputeGroup(const AtmosphereParameters& atm, const PrecomputeOptions& options,
                            const PrecomputeControl& control = {});

}  // namespace skyig::atmosphere
