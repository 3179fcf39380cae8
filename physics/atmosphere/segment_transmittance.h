#pragma once
// The air's transmittance along a segment of a view, weighted by the sun's spectrum into one
// luminance factor: what dims a cloud deck seen through the air in front of it (the weather's
// table, sky/fog_state.h) and the sunlight a deck scatters back to the eye (the sky pass's light
// table). From two transmittances to the top of the atmosphere (Bruneton & Neyret 2008, section
// 4: T(x, p) = T(x, top) / T(p, top) along the ray), the ray reversed where it goes down, so
// neither ratio crosses the ground.
#include "physics/atmosphere/model.h"

namespace skyig::atmosphere {

// From radius r along cosine mu (to the local vertical at r) for d metres.
double luminanceTransmittance(const AtmosphereModel& model, double r, double mu, double d);

}  // namespace skyig::atmosphere
