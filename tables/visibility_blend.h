#pragma once
// Tables for a visibility between two precomputed ones, blended on the CPU, so the sky follows
// a host's change of visibility at once while the exact tables are built (minutes on llvmpipe).
//
// The medium changes with the visibility only through the aerosol extinction beta_M
// (conditions.h: beta_M = 3.912 / V - beta_R at 550 nm), so the blend is made in beta_M, i.e.
// in 1/V, never in V. Along a ray the optical depth is linear in beta_M, so a transmittance is
// A exp(-c beta_M) and its logarithm blended linearly in beta_M between two steps is exact but
// for the tables' own interpolation. Light scattered by the aerosols and attenuated on its way
// behaves more like A beta_M^d exp(-c beta_M): with a third step the logarithm of every texel
// is fitted by a + b beta_M + d ln beta_M through the three (exact for both forms), and held
// between the two steps around the target. docs/atmosphere.md ("Visibility between cached
// steps") gives the errors of either against the exact tables and of linear blending.
#include <cstddef>
#include <optional>
#include <vector>

#include "physics/atmosphere/model.h"

namespace skyig::atmosphere {

// The visibilities (km) whose tables the node keeps, besides its configuration's own: a
// geometric ladder (a factor 2-2.5 apart, i.e. in aerosol extinction too) from fog to clear
// air, down to a 1 km fog. docs/atmosphere.md gives the error of a blend between neighbours.
std::vector<double> defaultVisibilityStepsKm();

// `base` with the aerosol extinction of visibility `km` (the medium's Rayleigh scattering
// unchanged), built as applyConditions does, so it is the same cache file a host asking for
// exactly that visibility gets. Throws std::invalid_argument for a visibility the medium cannot
// have.
ModelConfig configAtVisibility(const ModelConfig& base, double km);

// True when the two configurations differ in nothing but the aerosol extinction: tables of
// one may be blended towards the other.
bool differOnlyInAerosols(const ModelConfig& a, const ModelConfig& b);

// Where a target lies among the steps: between `lower` (less aerosol) and `upper`, at `weight`
// of the way in aerosol extinction (1/V), and `third`, the next step beyond `upper` (else beyond
// `lower`) when there is one. lower == upper (weight 0, no third) when the target is a step or
// outside the ladder (its nearest end stands in).
struct StepBracket {
  std::size_t lower;
  std::size_t upper;
  double weight;
  std::optional<std::size_t> third;
};

// The steps around `target` among `steps` (any order), or nullopt when the target differs from
// them in more than the aerosols, or when there are no steps.
std::optional<StepBracket> bracketSteps(const std::vector<ModelConfig>& steps, const ModelConfig& target);

// The tables of `target` blended from models that differ from it only in the aerosol
// extinction: `lower` and `upper` around it (less and more aerosol), and `third` (may be null)
// beyond either. Every texel lies between lower's and upper's. The result has the target's
// configuration and says where it comes from (AtmosphereModel::blendOrigin). Throws
// std::invalid_argument if the models do not fit.
AtmosphereModel blendModels(const AtmosphereModel& lower, const AtmosphereModel& upper, const AtmosphereModel* third,
                            const ModelConfig& target);

// `step`'s tables under the target's configuration (a visibility beyond the ladder's ends),
// marked as a blend of that step alone.
AtmosphereModel nearestStepModel(const AtmosphereModel& step, const ModelConfig& target);

}  // namespace skyig::atmosphere
