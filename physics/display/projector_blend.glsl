#ifndef SKYIG_TONE_PROJECTOR_BLEND_GLSL
#define SKYIG_TONE_PROJECTOR_BLEND_GLSL
// Edge blending of overlapping projectors, in light (VESA MPCDI v2, alpha and beta maps;
// Raskar et al. 1998, "The office of the future", section 4.2: the intensity weights of the
// projectors covering a point add up to 1). The tone pass gives the channel's display value n;
// its light relative to the projector's white is l = n^gamma (the display model of
// Wang, Ji & Zhang 2011, eq. 17). A projector pixel with blend weight alpha and black-level
// lift beta (both linear light, fractions of the projector's white) sends
//   l_out = beta + (1 - beta) alpha l,
// and is driven with n_out = l_out^(1 / gamma). Where k projectors overlap their alphas add up
// to 1, so their light adds up to one projector's; beta lifts the black of the pixels with fewer
// projectors so the summed black floor is the same everywhere.

// The drive value of one colour channel of a projector pixel.
Float blendedDisplayValue(Float n, Float alpha, Float beta, Float gamma) {
  Float l = pow(clamp(n, 0.0, 1.0), gamma);
  Float lOut = beta + (1.0 - beta) * clamp(alpha, 0.0, 1.0) * l;
  return pow(clamp(lOut, 0.0, 1.0), 1.0 / gamma);
}

// Each colour by its own weight and lift: an MPCDI alpha or beta map may hold one component
// (grey, the same for R, G and B) or three (componentDepth 3, one a colour channel).
vec3 blendedDisplayValues(IN(vec3) n, IN(vec3) alpha, IN(vec3) beta, Float gamma) {
  return vec3(blendedDisplayValue(n.x, alpha.x, beta.x, gamma), blendedDisplayValue(n.y, alpha.y, beta.y, gamma),
              blendedDisplayValue(n.z, alpha.z, beta.z, gamma));
}

#endif
