#ifndef SKYIG_COMMON_BAND_GLSL
#define SKYIG_COMMON_BAND_GLSL
// A pass's light in its channel's band (sky/nvis_weights.h): the linear Rec.709 radiance it
// computed, or in a goggle's band that light's NVIS radiance, its luminance times the light's
// weight, in all three channels. A uniform branch on one value: both sides are a few
// multiplies, so llvmpipe running both costs nothing worth a variant.
#include "render/glsl/band_uniforms.h"
#include "physics/common/color.glsl"

vec3 inBand(vec3 rec709, float nvisPerCdM2) {
  return band.x > 0.5 ? vec3(nvisPerCdM2 * rec709Luminance(rec709)) : rec709;
}
// The ratio of a light's weight to the sunlit sky's (1 in the eye's band): the physical sky pass
// weights its sum by the sunlit sky's weight at the end.
float bandRatio(float ratio) { return band.x > 0.5 ? ratio : 1.0; }

#endif
