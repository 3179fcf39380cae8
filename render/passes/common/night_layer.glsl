#ifndef SKYIG_NIGHT_NIGHT_LAYER_GLSL
#define SKYIG_NIGHT_NIGHT_LAYER_GLSL
// The night's layer (NightDiffusePass::drawLayer, render/passes/common/night_layer.h) at a channel's
// pixel: a grid of SKYIG_NIGHT_LAYER_CELL_PX-pixel cells (render/glsl/pixel_grid.glsl) holding in rgb
// the night's own light (above the atmosphere, or dimmed at its vertices: the renderer binds
// either) and in alpha, where the renderer asked for it, the veil per lux of the tone block's one
// glare source (render/passes/tone/glare_veil.glsl). GPU only.
#include "render/glsl/bindings.h"
#include "render/glsl/pixel_grid.glsl"

layout(binding = SKYIG_UNIT_NIGHT_LAYER) uniform sampler2D nightLayer;

vec4 nightLayerAt(vec2 fragCoord) { return pixelGridAt(nightLayer, fragCoord, SKYIG_NIGHT_LAYER_CELL_PX); }

#endif
