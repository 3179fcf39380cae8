#ifndef SKYIG_TONE_TONE_DISPLAY_GLSL
#define SKYIG_TONE_TONE_DISPLAY_GLSL
// What a channel's display is sent for one pixel: the world's light (linear Rec.709, cd/m^2)
// with the eye's glare veil added, mapped by the display's operator, the displayed point
// sources added in display luminance, encoded for the display (eq. 18) and dithered. One
// function for the two places that map pixels: the tone pass (render/passes/tone/tone.frag), and the
// physical sky pass when it is the frame's last full-screen pass (render/passes/sky/physical_sky.frag,
// SKYIG_FOLD_TONE), which maps the light it has just computed instead of writing it for a
// second pass to read back: the same code on the same float, so the same display value.
// GPU only (it reads the tone block). The variants are the tone pass's (render/passes/tone/tone.frag).
#include "render/glsl/tone_uniforms.h"
#include "render/glsl/display_curve.glsl"
#ifdef SKYIG_GLARE
#include "render/passes/tone/glare_veil.glsl"
#endif
#include "render/glsl/dither.glsl"

#ifdef SKYIG_GLARE_FROM_GRID
// The veil at the vertices of a grid of SKYIG_GLARE_CELL_PX-pixel cells (render/passes/tone/glare_veil.frag).
#include "render/glsl/pixel_grid.glsl"
layout(binding = SKYIG_UNIT_GLARE_VEIL) uniform sampler2D glareVeilGrid;
#elif defined(SKYIG_GLARE_FROM_NIGHT_LAYER)
// The veil per lux of the block's one glare source (SKYIG_GLARE 1) at the vertices of the
// night's layer, its alpha (render/passes/common/night_layer.glsl), as the including pass reads it: the sky
// pass from the read that gives it the night's light, the tone pass with a read of its own.
float nightLayerVeilPerLux(vec2 fragCoord);
#elif defined(SKYIG_GLARE)
#include "render/glsl/frame_uniforms.h"
#endif

vec4 toneDisplayValue(vec3 world, vec3 pointSources, vec2 fragCoord) {
#if defined(SKYIG_GLARE_FROM_GRID)
  world += pixelGridAt(glareVeilGrid, fragCoord, SKYIG_GLARE_CELL_PX).rgb;
#elif defined(SKYIG_GLARE_FROM_NIGHT_LAYER)
  world += glareLux[0].rgb * nightLayerVeilPerLux(fragCoord);
#elif defined(SKYIG_GLARE)
  world += glareVeil(mat3(ndcToWorld) * vec3(fragCoord * viewport.zw * 2.0 - 1.0, 1.0));
#endif
  DisplayModel model = toneDisplayModel();
  vec3 ld = toneMapLinear(world) + pointSources;
  vec3 n = displayValues(compressToDisplay(ld, rec709Luminance(ld), model.ambientLuminance + model.maxLuminance), model);
  return vec4(clamp(n + ditherLsb(fragCoord, adaptation.y), 0.0, 1.0), 1.0);
}

#endif
