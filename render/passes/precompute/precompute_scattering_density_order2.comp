// GPU precomputation, step 4a at order 2: the scattering density from single scattering, whose
// Rayleigh and Mie tables take their phase functions per direction (scatteringOfOrderUvwz).
// A program of its own rather than a branch in precompute_scattering_density.comp: llvmpipe
// runs both sides of a branch, so orders 3 and up would pay for these fetches too.
#define SKYIG_DENSITY_FROM_SINGLE_SCATTERING 1
#include "render/passes/precompute/precompute_scattering_density.comp"
