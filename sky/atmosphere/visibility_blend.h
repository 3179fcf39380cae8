#pragma once
// Tables for a visibility between two precomputed ones, blended on the CPU, so the sky follows
// a host's change of visibility at once while the exact tables are built (minutes on llvmpipe).
//
// The medium changes with the visibility only through the aerosol extinction beta_M
// (conditions.h: beta_M = 3.912 / V - beta_R at 550 nm), so the blend is made in beta_M, i.e.
// in 1/V, never in V. Along a ray the optical depth is linear in beta_M, so the transmittance
// blended geometrically (T1^(1-w) T2^w) is exact but for the tables' own interpolation; the
// scattered light and the sky irradiance, which grow with the aerosols and fall with their
// extinction, are blended geometrically too where both steps are positive (measured against
// linear blending in docs/atmosphere.md, "Visibility between cached steps").
#include <cstddef>
#include <optional>
#include <vector>

#include "sky/atmosphere/model.h"

namespace skyig::atmosphere {

// The visibilities (km) whose tables the node keeps, besides its configuration's own: a
// geometric ladder (a factor 2-2.5 apart, i.e. in aerosol extinction too) from fog to clear
// air. docs/atmosphere.md gives the error of a blend between neighbours.
std::vector<double> defaultVisibilityStepsKm();

// `base` with the aerosol extinction of visibility `km` (the medium's Rayleigh scattering
// unchanged), built as applyConditions does, so it is the same cache file a host asking for
// exactly that visibility gets. Throws std::invalid_argument for a visibility the medium cannot
// have.
ModelConfig configAtVisibility(const ModelConfig& base, double km);

// True when the two configurations differ in nothing but the aerosol extinction: tables of
// one may be blended towards the other.
bool differOnlyInAerosols(const ModelConfig& a, const ModelConfig& b);

// Where a target lies between two steps: the blend is lower * (1 - weight) + upper * weight
// (geometrically). weight 0 or 1 when the target is a step, or outside the ladder (clamped to
// its end: the nearest step is shown).
struct StepBracket {
  std::size_t lower;
  std::size_t upper;
  double weight;
};

// The steps around `target` among `steps` (any order), or nullopt when the target differs from
// them in more than the aerosols, or when there are no steps.
std::optional<StepBracket> bracketSteps(const std::vector<ModelConfig>& steps, const ModelConfig& target);

// The tables of `target` blended from two models that differ from it only in the aerosol
// extinction, with the weight of `upper` (0 gives `lower`'s tables, 1 `upper`'s). The result
// has the target's configuration. Throws std::invalid_argument if the models do not fit.
AtmosphereModel blendModels(const AtmosphereModel& lower, const AtmosphereModel& upper, double weight,
                            const ModelConfig& target);

}  // namespace skyig::atmosphere
