#ifndef SKYIG_RENDER_CLOUD_FIELD_GLSL
#define SKYIG_RENDER_CLOUD_FIELD_GLSL
// The broken decks' fields along a pixel's view (SKYIG_CLOUD_COVER n, 1-3: the number of broken
// decks is the variant's, not a uniform: a loop of constant length unrolls to constant indices,
// where a uniform count left llvmpipe a loop and a gather per lane for every uniform it indexed,
// a third of a broken deck's cost in the sky pass). The field is physics/weather/cloud_cover.glsl,
// placed by the CPU (physics/weather/cloud_deck.h; render/passes/common/cloud_field.h uploads it);
// the sky pass and the night's diffuse light read the same one, so a gap shows the same sky in both.
#include "physics/weather/cloud_cover.glsl"
#include "physics/weather/fog_table.glsl"

uniform vec4 cloudDeckShape[3]; // middle height above the ground (m), cell (m), threshold, softness
uniform vec4 cloudDeckPlace[3]; // origin (cells), stretch across the wind, seed
uniform vec4 cloudDeckAlong[3]; // the wind's direction (east, north), the coverage, the fade's start (m)
uniform vec2 cloudEye;          // the eye above the ground (m), the ground's radius (m)

// The share of cloud broken deck k has where the view crosses its middle height.
float cloudShareOf(int k, vec3 view) {
  float d = distanceToHeight(cloudEye.y, cloudEye.x, view.z, cloudDeckShape[k].x);
  if (d < 0.0) return 0.0;
  vec2 offset = view.xy * d;  // metres east and north where the view crosses the middle
  vec2 along = cloudDeckAlong[k].xy;
  vec2 p = cloudDeckPlace[k].xy + vec2(dot(offset, along), dot(offset, vec2(along.y, -along.x)) * cloudDeckPlace[k].z) /
                                      cloudDeckShape[k].y;
  float mask = cloudMask(p, int(cloudDeckPlace[k].w), cloudDeckShape[k].z, cloudDeckShape[k].w);
  // Far off, where a cell shrinks below a few pixels, the field's mean (its coverage) instead
  // of noise that would alias (cloudFadeWeight).
  return mix(mask, cloudDeckAlong[k].z, cloudFadeWeight(d, cloudDeckAlong[k].w));
}

// Each broken deck's share along this pixel's view, evaluated once (the sky and the decks'
// single-scattered light read it).
vec3 cloudShares = vec3(0.0);
// The share of the view that meets a broken deck's cloud: the most of any deck's.
float cloudShareAlong(vec3 view) {
  float share = 0.0;
  for (int k = 0; k < SKYIG_CLOUD_COVER; ++k) {
    cloudShares[k] = cloudShareOf(k, view);
    share = max(share, cloudShares[k]);
  }
  return share;
}

// What reaches the eye from beyond the decks along this view (the night's own light: airglow,
// zodiacal light, the Milky Way) over what the state's extinction profile lets through, which
// weighs a broken deck by its coverage (sky/fog_state.h, cloudFieldFactor, the CPU's for a star):
// 0 behind a thick cloud, over 1 in a gap. `clear` and `clouded` are the weather tables' alphas
// along the view without the broken decks and with their gaps filled; the view meets them as the
// sky pass mixes its layers, by `share`. The profile's mean is 1 - c (1 - T) for one deck of
// coverage c and transmittance T: exact for one broken deck; for several, their fields taken as
// independent, 1 - prod(1 - c_k) stands for c (exact where each deck is opaque). The tables'
// alpha also keeps the share of the air's light that lies in front of a deck (physics/weather/
// fog_table.cpp, compose), so behind a thick cloud about 1 % of the night's light stays (that
// share, 1 - the air's transmittance to the deck, times its shade): a star's ray has none.
float cloudFieldFactor(float clear, float clouded, float share) {
  float gap = 1.0;
  for (int k = 0; k < SKYIG_CLOUD_COVER; ++k) gap *= 1.0 - cloudDeckAlong[k].z;
  float expected = mix(clear, clouded, 1.0 - gap);
  return expected > 0.0 ? mix(clear, clouded, share) / expected : 1.0;
}

#endif
