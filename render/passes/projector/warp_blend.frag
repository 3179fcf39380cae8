// Warp and blend of a projector (VESA MPCDI v2: geometry warp, alpha and beta maps): for each
// projector pixel, the point of the channel's image it shows (the warp map, u right and v down
// from the image's top-left, NaN where it shows nothing), read bilinearly from the channel's
// undithered display values, blended in light (physics/display/projector_blend.glsl), dithered to 8 bits;
// and the channel's HDR light at that point times alpha, the light this projector contributes,
// so the projectors' light images add up to the sky's.
//
// The maps may be coarser than the projector: their first and last samples sit on the centres
// of the projector's first and last pixels (rows from the top) and they are interpolated
// bilinearly between (texture filtering), so a map at the projector's size is read texel for
// pixel.
#include "render/glsl/uniforms.h"
#include "render/glsl/dither.glsl"
#include "physics/display/projector_blend.glsl"

layout(binding = SKYIG_UNIT_CHANNEL_DISPLAY) uniform sampler2D channelDisplay;  // undithered n
layout(binding = SKYIG_UNIT_CHANNEL_HDR) uniform sampler2D channelHdr;          // cd/m^2
// The warp as (u, v, 1) where mapped and (0, 0, 0) where the file has NaN: filtering NaN would
// spread it to the neighbours (0 * NaN is NaN), so the pass renormalises by the mapped weight.
layout(binding = SKYIG_UNIT_PROJECTOR_WARP) uniform sampler2D warpMap;
layout(binding = SKYIG_UNIT_PROJECTOR_ALPHA) uniform sampler2D alphaMap;
layout(binding = SKYIG_UNIT_PROJECTOR_BETA) uniform sampler2D betaMap;
layout(location = SKYIG_OUTPUT_PROJECTOR_DISPLAY) out vec4 outDisplay;
layout(location = SKYIG_OUTPUT_PROJECTOR_LIGHT) out vec4 outLight;

// The texture coordinate of `map` at the projector pixel `pixel` (0-based, rows from the top).
// The maps' rows are uploaded from the top too, so texture row 0 is their top row.
vec2 mapCoord(sampler2D map, vec2 pixel) {
  vec2 size = vec2(textureSize(map, 0));
  vec2 grid = pixel * (size - 1.0) / max(projector.xy - 1.0, vec2(1.0));
  return (grid + 0.5) / size;
}

void main() {
  vec2 pixel = vec2(gl_FragCoord.x - 0.5, projector.y - gl_FragCoord.y - 0.5);
  vec3 warp = texture(warpMap, mapCoord(warpMap, pixel)).rgb;
  vec2 uv = warp.xy / max(warp.z, 1e-6);
  // Unmapped (mostly NaN samples around it, or a point outside the rendered image): nothing
  // sent, not even the black lift.
  if (warp.z < 0.5 || any(lessThan(uv, vec2(-1e-4))) || any(greaterThan(uv, vec2(1.0 + 1e-4)))) {
    outDisplay = vec4(0.0, 0.0, 0.0, 1.0);
    outLight = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  vec2 st = vec2(uv.x, 1.0 - uv.y);  // the channel's GL rows start at the bottom
  // One component maps are read as grey (their texture swizzles red into green and blue).
  vec3 alpha = clamp(texture(alphaMap, mapCoord(alphaMap, pixel)).rgb, 0.0, 1.0);
  vec3 beta = clamp(texture(betaMap, mapCoord(betaMap, pixel)).rgb, 0.0, 1.0);
  vec3 n = blendedDisplayValues(texture(channelDisplay, st).rgb, alpha, beta, blend.x);
  outDisplay = vec4(clamp(n + ditherLsb(gl_FragCoord.xy, blend.y), 0.0, 1.0), 1.0);
  outLight = vec4(texture(channelHdr, st).rgb * alpha, 1.0);
}
