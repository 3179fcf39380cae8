#pragma once
// The display mapping a physical sky pass does in its own fragment (render/passes/sky/physical_sky.frag,
// SKYIG_FOLD_TONE), as the tone pass gives it (TonePass::folded): its variant with the glare
// veil read from a grid everywhere (its own, or the night's layer that holds it), and the variant
// with the veil per pixel in the boxes around the glare sources, where the grid's interpolation
// would err (render/passes/tone/tone_pass.h).
// Mapping the boxes in the sky pass maps each of their pixels once, where mapping them with the
// grid's veil and again in the tone pass mapped them twice.
#include <glm/vec4.hpp>

#include <string>
#include <vector>

namespace skyig::render {

struct FoldedTone {
  std::string defines;                 // the tone pass's variant; empty: the HDR image only
  std::string exactDefines;            // the same with the veil per pixel, for the boxes
  std::vector<glm::ivec4> exactBoxes;  // pixels: x, y, width, height, within the viewport
};

}  // namespace skyig::render
