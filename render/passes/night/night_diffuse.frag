// The diffuse night light, added to the sky pass's radiance (blend ONE, ONE): the Milky Way and
// the unresolved stars (a calibrated panorama, S10 per channel), the zodiacal light (Leinert et
// al. 1998 table 17, S10) and the airglow (van Rhijn), all dimmed by the transmittance to space
// along the view. Below the horizon, the terrain as that light shows it (SkyState::
// nightGroundRadiance). The CPU twin is physics/night/night_diffuse.h.
// SKYIG_NIGHT_LAYER: the sky's part alone, above the atmosphere (no transmittance), without
// blending, into the small target of NightDiffusePass::drawLayer, which the physical sky pass
// reads bilinearly, dims by the transmittance and adds with the terrain's step, both at full
// resolution (render/passes/sky/physical_sky.frag): what changes fast at the horizon is per pixel. Beside
// it (SKYIG_OUTPUT_NIGHT_LAYER_TRANSMITTED) the same light dimmed at the texel, which the sky
// pass reads as it is more than kNightLayerBandDeg above the horizon, where the transmittance
// is smooth over a texel (render/passes/common/night_layer.h). The layer is a grid of views through
// pixel corners (render/passes/common/night_layer.glsl); with SKYIG_GLARE 1 its alpha holds the glare veil per
// lux of the tone block's one glare source, which the sky pass then reads with the light.
#include "render/glsl/bindings.h"
#include "physics/night/units.glsl"
#include "physics/night/milky_way.glsl"
#include "physics/night/zodiacal.glsl"
#include "physics/night/airglow.glsl"
#include "render/glsl/band.glsl"
#include "physics/night/transmittance_to_space.glsl"
#include "render/glsl/edge_coverage.glsl"

uniform mat3 enuToJ2000;
uniform vec3 sunJ2000;
uniform vec3 sunlightRec709;   // luminance 1
uniform vec3 airglowZenith;    // linear Rec.709, cd/m^2
uniform vec3 nightGroundRadiance;  // linear Rec.709, cd/m^2: the terrain under the night's light
layout(binding = SKYIG_UNIT_MILKY_WAY) uniform sampler2D milkyWayS10;
layout(binding = SKYIG_UNIT_ZODIACAL) uniform sampler2D zodiacalS10;
layout(binding = SKYIG_UNIT_NIGHT_EXTINCTION) uniform sampler1D extinctionRec709;

in vec3 vViewRay;
layout(location = SKYIG_OUTPUT_COLOR) out vec4 outRadiance;
#ifdef SKYIG_NIGHT_LAYER
layout(location = SKYIG_OUTPUT_NIGHT_LAYER_TRANSMITTED) out vec4 outTransmitted;
#endif

#ifdef SKYIG_CLOUD_COVER
// Through a broken deck (the full-screen pass only, which a goggle draws; the eye's channels take
// the layer's light through it in the sky pass): behind its cloud or in a gap, where the sky
// pass's field has them, from the sky pass's two weather tables (PhysicalSkyPass::cloudField).
#include "render/passes/common/cloud_field.glsl"
layout(binding = SKYIG_UNIT_FOG_TABLE) uniform sampler1D fogTable;
layout(binding = SKYIG_UNIT_FOG_CLEAR_TABLE) uniform sampler1D fogClearTable;
#endif
#ifdef SKYIG_NIGHT_LAYER
#include "render/glsl/pixel_grid.glsl"
#ifdef SKYIG_GLARE
#include "render/passes/tone/glare_veil.glsl"
#endif
#endif

void main() {
#ifdef SKYIG_NIGHT_LAYER
  // A texel a vertex of the layer's grid (render/passes/common/night_layer.glsl).
  vec3 view = normalize(pixelGridView(gl_FragCoord.xy, SKYIG_NIGHT_LAYER_CELL_PX));
#else
  vec3 view = normalize(vViewRay);
#endif
#ifdef SKYIG_NIGHT_LAYER
  const vec3 t = vec3(1.0);  // the sky pass applies it per pixel near the horizon, where it is steep
#else
  vec3 t = transmittanceToSpace(extinctionRec709, view);
#ifdef SKYIG_CLOUD_COVER
  t *= cloudFieldFactor(texture(fogClearTable, fogTableU(view.z)).a, texture(fogTable, fogTableU(view.z)).a,
                        cloudShareAlong(view));
#endif
#endif
  vec3 j2000 = enuToJ2000 * view;
  // The panorama's u jumps from 1 to 0 at RA 90 deg: take the mip level from the gradient of a
  // copy that is continuous there, so the seam does not pick the coarsest level.
  vec2 uv = milkyWayTexCoord(j2000);
  vec2 uvShifted = vec2(fract(uv.x + 0.5), uv.y);
  vec2 dx = dFdx(uv), dy = dFdy(uv);
  vec2 dxS = dFdx(uvShifted), dyS = dFdy(uvShifted);
  if (abs(dxS.x) + abs(dyS.x) < abs(dx.x) + abs(dy.x)) {
    dx = dxS;
    dy = dyS;
  }
  vec3 milkyWay = kS10CdM2 * textureGrad(milkyWayS10, uv, dx, dy).rgb;
  vec2 lonLat = helioEclipticCoordinates(j2000, sunJ2000);
  vec3 zodiacal = s10ToCdM2(texture(zodiacalS10, zodiacalTexCoord(lonLat)).r) * sunlightRec709;
  vec3 airglow = airglowRadiance(airglowZenith, view.z);
  vec3 sky = inBand(t * milkyWay, nightWeights.x) + inBand(t * zodiacal, lightWeights.w) + inBand(t * airglow, lightWeights.z);
#ifdef SKYIG_NIGHT_LAYER
#ifdef SKYIG_GLARE
  float veil = glareVeilPerLux(view, 0);  // the tone's, where the sky pass reads the layer anyway
#else
  const float veil = 0.0;
#endif
  outRadiance = vec4(sky, veil);
  outTransmitted = vec4(transmittanceToSpace(extinctionRec709, view) * sky, veil);
#else
  // The terrain below the geometric horizon by its share of the pixel (render/glsl/edge_coverage.glsl).
  outRadiance = vec4(sky + (1.0 - pixelShareAbove(view.z)) * inBand(nightGroundRadiance, nightWeights.y), 0.0);
#endif
}
