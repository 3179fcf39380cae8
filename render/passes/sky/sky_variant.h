#pragma once
// A variant of the physical sky pass's fragment (render/passes/sky/physical_sky.frag): which of
// its blocks one program compiles, as a typed configuration that writes its own #defines (the
// pattern of Magnum's shader flags), so the pass names what it draws instead of concatenating
// define strings. llvmpipe runs both sides of a branch for every pixel: a frame pays only for
// what it shows by drawing the variant that has only that.
#include "render/passes/common/night_layer.h"

#include <compare>
#include <string>

namespace skyig::render {

struct SkyVariant {
  // Which rays it draws: both (a target without depth), the sky's (where the ground's wrote no
  // depth), the ground's (first, on the cap below the horizon), or the sky within
  // kNightLayerBandDeg of the horizon (a cap like the ground's) when the night's layer is added,
  // or the pixels the horizon crosses, both rays by their shares of the pixel, drawn over the
  // others on a strip around the horizon (render/passes/sky/horizon_strip.vert).
  enum class Part { both, sky, ground, horizonBand, horizonEdge };
  Part part = Part::both;
  bool moonlit = false;                // SKYIG_MOONLIT: the moon's sky and ground too
  bool sunDisc = false;                // SKYIG_SUN_DISC: on the quad around the sun
  bool sunless = false;                // SKYIG_SUNLESS: without the sun's sky and ground
  bool nightLayer = false;             // SKYIG_NIGHT_LAYER: the night's own light added
  int nightLayerCellPx = 0;            // its cell, pixels (SKYIG_NIGHT_LAYER_CELL_PX)
  bool nightLayerTransmitted = false;  // SKYIG_NIGHT_LAYER_TRANSMITTED: the layer already dimmed
  bool fog = false;                    // SKYIG_FOG: the weather's layers composed (one of them is on)
  int cloudCover = 0;                  // SKYIG_CLOUD_COVER n: with it, the n broken decks' fields per pixel
  int cloudLight = 0;                  // SKYIG_CLOUD_LIGHT n: with it, the n lit decks' single-scattered sun and moon
  std::string tone;                    // SKYIG_FOLD_TONE with the tone pass's defines; empty: HDR only

  // The #define lines, in the order the blocks are read.
  std::string defines() const {
    std::string d;
    if (moonlit) d += "#define SKYIG_MOONLIT\n";
    if (part == Part::sky || part == Part::horizonBand) d += "#define SKYIG_SKY\n";
    if (part == Part::horizonBand) d += "#define SKYIG_HORIZON_BAND\n";
    if (part == Part::ground) d += "#define SKYIG_GROUND\n";
    if (part == Part::horizonEdge) d += "#define SKYIG_HORIZON_EDGE\n";
    if (sunDisc) d += "#define SKYIG_SUN_DISC\n";
    if (sunless) d += "#define SKYIG_SUNLESS\n";
    if (fog) d += "#define SKYIG_FOG\n";
    // The decks' counts are the variant's, not uniforms: their loops unroll (physical_sky.frag).
    if (fog && cloudCover > 0) d += "#define SKYIG_CLOUD_COVER " + std::to_string(cloudCover) + "\n";
    if (fog && cloudLight > 0) d += "#define SKYIG_CLOUD_LIGHT " + std::to_string(cloudLight) + "\n";
    if (nightLayer)
      d += "#define SKYIG_NIGHT_LAYER\n" + nightLayerCellDefine(nightLayerCellPx);
    if (!tone.empty()) d += "#define SKYIG_FOLD_TONE\n" + tone;
    if (nightLayerTransmitted) d += "#define SKYIG_NIGHT_LAYER_TRANSMITTED\n";
    return d;
  }
  // The vertex stage: the horizon's strip, the disc's quad, the cap below a ring, or the
  // full-screen triangle.
  const char* vertexShader() const {
    if (part == Part::horizonEdge) return "render/passes/sky/horizon_strip.vert";
    if (sunDisc) return "render/passes/sky/sun_disc.vert";
    if (part == Part::ground || part == Part::horizonBand) return "render/passes/sky/ground_cap.vert";
    return "render/glsl/fullscreen.vert";
  }
  // Whether this frame's tone or night layer asks for more than the HDR sky.
  bool extended() const { return nightLayer || !tone.empty(); }
  auto operator<=>(const SkyVariant&) const = default;
};

}  // namespace skyig::render
