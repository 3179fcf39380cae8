#pragma once
// The weather's layers along every view of one eye, tabulated by the view's cosine
// (fog_table.glsl): what the sky pass composes per pixel with one texture read. Each entry is the
// layers' own light added along the view (linear Rec.709 cd/m^2) and the transmittance of what
// lies behind them, composed in the layers' order exactly as throughFog composes them.
#include <glm/vec4.hpp>

#include <functional>
#include <vector>

#include "physics/weather/fog_layer.h"

namespace skyig::weather {

// Texels of the table: at 2048 a texel spans 0.011 deg at the top of a fog 300 m below the eye
// and 0.03 deg at a 12 km eye's horizon, under a pixel of a 60 deg, 1920 pixel channel.
inline constexpr int kFogTableSize = 2048;

// The clear air's transmittance from the eye along a view of cosine mu for d metres (one
// luminance factor): what a cloud deck is seen through. Null: none (1).
using AirTransmittance = std::function<double(double mu, double d)>;

// The table for an eye heightM above the ground: entry i at mu = fogTableMu((i + 0.5) / size), its
// ray ending at the ground where it meets it. Layers of extinction 0 add nothing. A deck beyond
// air of transmittance T_a is seen as T_a of itself over the air's own light in front, taken as
// 1 - T_a of the clear air's light along the view (in the deck's shade, fogShadeBelow, when the
// eye is under it), so a far deck fades into the haze before it.
std::vector<glm::vec4> fogTable(const FogLayers& layers, double heightM, int size = kFogTableSize,
                                const AirTransmittance& air = nullptr);

// The same composition for one view: in-scattered light (rgb) and transmittance (a).
glm::dvec4 fogAlong(const FogLayers& layers, double heightM, double mu, const AirTransmittance& air = nullptr);
// The same for the first d metres of the view (a segment to a surface, d from the eye): every
// composite of the layers (the sky pass's table, the eye's view sphere, the library's light and
// aerial perspective) is this one.
glm::dvec4 fogAlong(const FogLayers& layers, double heightM, double mu, double d, const AirTransmittance& air = nullptr);

}  // namespace skyig::weather
