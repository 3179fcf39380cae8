#pragma once
// A host's cloud layer (physics/common/cloud_layer.h) as the sky draws it: a slab of the weather's
// layer model (fog_layer.glsl: grey extinction, Bohren's two-stream light, the transition bands)
// between its base and top, its extinction from the type's droplets or crystals, lit at its top
// by the sun, the moon and the sky the tables give there, so a low sun reddens its base; and,
// where the coverage is below 100 %, the field that says where it has cloud (cloud_cover.glsl),
// fixed to the ground and moved by the layer's wind on the host's clock. docs/clouds.md says why.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "physics/common/cloud_layer.h"
#include "physics/common/sky_conditions.h"
#include "physics/weather/fog_layer.h"

namespace skyig::weather {

// What the droplets (or crystals) of a type do to light in the visible: the extinction per metre
// and the asymmetry of their phase function.
struct CloudOptics {
  double extinctionPerM = 0.0;
  double asymmetry = sky::kDropletAsymmetry;
};

// The type's optics (cloud_deck.cpp: the water or ice content and the effective radius behind
// each, the content scaled by the severity), or, where the host gives the visibility inside
// (CIGI's Visibility Range), Koschmieder's 3.912 / V with the type's asymmetry.
CloudOptics cloudOptics(const sky::CloudLayer& layer);

// The water (or ice) content of a severity against the type's typical one (severity 2): CIGI
// leaves the severity's meaning to the IG; here its six steps span, geometrically, the factor 6
// that aircraft measure within one type (low stratiform cloud 0.1-0.6 g/m^3: Miles, Verlinde
// and Clothiaux 2000), 6^((s - 2) / 5): 0.49 at 0, 1 at 2, 2.93 at 5. The extinction, and so
// the visibility inside, follows the content at the type's droplet size.
double severityContentFactor(int severity);

// The layer's slab: from its base to its top, the base's transition band as the fog's (both
// edges soft by it), its visibility inside from cloudOptics.
sky::FogSpec deckSpec(const sky::CloudLayer& layer);

// The exponent b of the law (1 + b mu) / (1 + 2 b / 3) a deck's base and top shine by (Moon &
// Spencer 1942, the CIE's standard overcast sky: b = 2): a thick cloud's boundary is brighter
// along its normal than at grazing views, as diffusion through it leaves it.
inline constexpr double kDeckLimbDarkening = 2.0;

// The layer as a FogLayer lit at its top by topIrradiance (linear Rec.709 lux from above, on a
// horizontal surface), over a planet of radius planetRadiusM with a ground of groundAlbedo; its
// gap is 1 - coverage (the expected share of sky it leaves clear, what the eye's adaptation and
// the night's light weigh). Throws std::invalid_argument for a layer validate() refuses.
FogLayer makeCloudDeck(const sky::CloudLayer& layer, double planetRadiusM, double groundAlbedo,
                       const glm::dvec3& topIrradiance);

// Where a broken layer has cloud, for one frame: its field's lattice (cells of cellM metres,
// cloud_cover.glsl) placed under the eye. origin is the eye's point in cells modulo the field's
// period (double on the CPU, so the GPU's floats hold it anywhere); the field is sampled at its
// middle height, `stretch` times finer across the wind than along it (cirrus streaks).
struct CloudCover {
  bool broken = false;  // coverage below 100 %: the sky pass draws the field
  double midHeightM = 0.0;
  double cellM = 1.0;
  double threshold = 0.0;
  double softness = 0.0;
  double stretch = 1.0;
  glm::dvec2 origin{0.0};  // cells, in [0, kCloudPeriodCells)
  glm::dvec2 along{0.0, 1.0};  // unit, east/north: the wind's direction (north when calm)
  int seed = 0;
  double coverage = 0.0;  // in [0, 1]
};

// Where the sky pass begins to draw a broken deck's field by its mean: this many cells away (8 km
// for cumulus), where a cell spans under ~6 pixels of a 1920-pixel, 60 deg channel at the
// horizon's grazing views; by 4 times that, all mean (cloudFadeWeight).
inline constexpr double kCloudFadeCells = 8.0;

// The field's threshold for a coverage in [0, 1]: the field's quantile (sampled once over its
// period) at which the share of ground where cloudMask passes 1 - 1/e is the coverage.
double cloudThreshold(double coverage, double softness);

// Layer `index`'s field for an eye at eastM, northM (metres on the ground, cloudGroundPosition)
// at timeS seconds of the host's clock: the layer moved downwind by speed * timeS.
CloudCover cloudCoverOf(const sky::CloudLayer& layer, int index, double eastM, double northM, double timeS);

// A point's metres east and north on the ground (the equirectangular map about its own
// latitude): what two nodes at the same ownship agree on to the bit.
glm::dvec2 cloudGroundPosition(double latitudeDeg, double longitudeDeg, double planetRadiusM);

// The share of cloud the field puts at `offsetM` metres (east, north) from the eye, at its middle
// height: the sky pass's cloudMask as the CPU computes it (tests, the probe).
double cloudShareAt(const CloudCover& cover, const glm::dvec2& offsetM);

}  // namespace skyig::weather
