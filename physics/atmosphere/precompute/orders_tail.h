#pragma once
// The orders of scattering after the last one computed, summed as a geometric series. Past the
// first few orders, successive orders of scattering in a plane-parallel medium shrink by a near
// constant factor q, the largest eigenvalue of the scattering operator (the light one order
// passes on to the next), so the orders left sum to L_n (q + q^2 + ...) = L_n q / (1 - q): the
// closure of Hillaire 2020 ("A Scalable and Production Ready Sky and Atmosphere Rendering
// Technique", EGSR), whose multiple-scattering transfer F_ms = 1 / (1 - f_ms) sums the orders
// with one ratio, and the geometric extrapolation of successive-orders-of-scattering solvers.
// q is measured as the ratio of the last two orders summed over the whole table, per wavelength
// (a texel's own ratio is noisy while the angular shape of the orders still changes: it
// overshot sixteen orders threefold at 5 km visibility).
#include <glm/vec4.hpp>

#include "physics/atmosphere/atmosphere_physics.h"
#include "physics/atmosphere/precompute/tables.h"

namespace skyig::atmosphere {

using shader::atmosphere_types::AtmosphereParameters;

// The largest ratio the tail is added for (four orders' worth of the last). Measured on
// four orders of a one-group model, sun-lit sky (q at 550 nm): 0.34 at 40 km visibility, 0.66
// at 10 km; 0.87 at 5 km, 0.99 at 2 km, 1.1-1.5 below 0.5 km, where the orders still grow and a
// geometric tail has no meaning (the tail was then left out: the fog is the fog layer's work).
inline constexpr double kOrdersTailMaxRatio = 0.8;

// q per wavelength: the last order's radiance summed over the table over the one before's; all
// zero (no tail) where any wavelength's exceeds kOrdersTailMaxRatio.
glm::dvec4 ordersRatio(const shader::cpu_texture::sampler3D& before, const shader::cpu_texture::sampler3D& last);

// Adds the tail of the orders to the scattering table (the last order's radiance per texel over
// the Rayleigh phase function of its nu, as the orders are stored) and to the irradiance table
// (from the last order's indirect irradiance), with q from ordersRatio(before, last).
void addOrdersTail(const AtmosphereParameters& atm, const shader::cpu_texture::sampler3D& before,
                   const shader::cpu_texture::sampler3D& last, const shader::cpu_texture::sampler2D& lastIrradiance,
                   GroupTables& tables);

}  // namespace skyig::atmosphere
