#pragma once
// The sky states a renderer draws, nothing shown, before its first frame, so that no frame of
// the day the host flies compiles a program (docs/performance.md, "Programs before the first
// frame"). A frame's programs follow its light (the sun's sky, the moon's, the night's layer,
// the eye's mesopic and point-source passes: sky/shown_layers.h) and its weather; compiled in
// the frame that first needs them they cost that frame a second on llvmpipe, tens of
// milliseconds on a GPU. One code for the node (before its first frame) and the library
// (SkyDraw::prepare).
#include "sky/channel.h"
#include "sky/sky_state.h"

#include <vector>

namespace skyig::render {

// `first`, then the observer's day at its place, sampled every half hour of local solar time,
// keeping each state whose shown layers (sky/shown_layers.h) or number of glare sources giving
// light no earlier one had: the day with and without the moon up, the twilights, the night with
// and without the moon as that day has them. Under the physical sky
// each again with a ground fog (the weather's program), and the first under a broken cloud deck
// over that fog (the cloud programs). Each mapped for `displays`.
std::vector<skyig::sky::SkyState> warmUpStates(const skyig::sky::SkyState& first,
                                               const std::vector<skyig::sky::DisplayParams>& displays);

// The attitudes a warm-up draws `state` from: `own`, and turned to each glare source that gives
// light (the sun, the moon), whose veil near the view is drawn exactly by programs of its own
// (render/passes/tone/folded_tone.h).
std::vector<skyig::sky::Attitude> warmUpAttitudes(const skyig::sky::SkyState& state, const skyig::sky::Attitude& own);

}  // namespace skyig::render
