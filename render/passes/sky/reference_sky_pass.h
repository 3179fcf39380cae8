#pragma once
// The reference the sky pass is measured against: skyig's physical sky pass of 2026-11-24,
// frozen in render/passes/sky/physical_sky_reference.frag (its header says why), drawn by a
// PhysicalSkyPass through the same inputs as the live one. `skyig bench --ratios` reports the
// live pass as a ratio of it, measured in the same run.
#include "render/passes/sky/physical_sky_pass.h"

#include <memory>

namespace skyig::render {

inline constexpr const char* kReferenceSkyFragment = "render/passes/sky/physical_sky_reference.frag";

// The reference's per-pixel cost against Bruneton & Neyret's 2017 demo pass (their
// precomputed-atmospheric-scattering demo, 3 wavelengths): 0.38 (0.36-0.40 over interleaved
// rounds), process CPU per pixel on llvmpipe, one thread, 1280x1024, on the 2-core machine of
// docs/performance.md. Times a live/reference ratio, an estimate of the live pass against
// Bruneton's.
inline constexpr double kReferenceOverBruneton2017 = 0.38;

// Needs the GL context current, as PhysicalSkyPass does.
inline std::unique_ptr<PhysicalSkyPass> makeReferenceSkyPass() {
  return std::make_unique<PhysicalSkyPass>(PhysicalSkyPass::kDefaultSlicesPerFrame, kReferenceSkyFragment);
}

}  // namespace skyig::render
