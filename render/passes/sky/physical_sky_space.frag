// The physical sky pass seen from above the atmosphere (physical_sky.frag is the IG's usual
// case): the general packedViewRec709 of physics/atmosphere/rendering_rec709.glsl for the sun and,
// when moonlightOn, the moon (Jensen et al. 2001).
#include "render/passes/sky/physical_sky_uniforms.glsl"
#include "render/glsl/band.glsl"

void main() {
  vec3 view = normalize(vViewRay);
  vec3 rgb = packedViewRec709(atm, transmittanceXyz, scatteringPacked, singleMieRG, irradianceXyz,
                              solarIrradianceXyz, limbDarkeningXyz, groundAlbedo, camera, view,
                              sunDirectionP, true);
  if (moonlightOn) {
    rgb += bandRatio(band.z) * moonlightScale * packedViewRec709(atm, transmittanceXyz, scatteringPacked, singleMieRG,
                                             irradianceXyz, solarIrradianceXyz, limbDarkeningXyz,
                                             groundAlbedo, camera, view, moonDirectionP, false);
  }
  outRadiance = vec4(max(inBand(rgb, lightWeights.x), vec3(0.0)), 1.0);
}
