#ifndef SKYIG_TONE_GLARE_VEIL_GLSL
#define SKYIG_TONE_GLARE_VEIL_GLSL
// The veil of the tone block's glare sources (physics/eye/glare.glsl) along a view: the first
// SKYIG_GLARE of them, those that give light (the renderer puts them first). GPU only (it
// reads the block); the tone pass evaluates it per pixel near a source and at the vertices of
// a grid elsewhere (render/passes/tone/glare_veil.frag, render/passes/tone/tone_pass.h), or, on a night with one
// glare source, of the night's layer (render/passes/night/night_diffuse.frag, render/passes/common/night_layer.h).
#include "render/glsl/tone_uniforms.h"
#include "physics/eye/glare.glsl"

// The veil per lux of the block's glare source i along `view`, of any length: the angle, the
// atan of |cross| over dot (accurate at the small angles where acos of a float is not), does not
// depend on it.
float glareVeilPerLux(vec3 view, int i) {
  vec3 d = glareDirection[i].xyz;
  float thetaDeg = degrees(atan(length(cross(view, d)), dot(view, d)));
  return veilPerLux(thetaDeg, glareDirection[i].w, glareCoefficients);
}

vec3 glareVeil(vec3 view) {
  vec3 veil = vec3(0.0);
  for (int i = 0; i < SKYIG_GLARE; ++i) veil += glareLux[i].rgb * glareVeilPerLux(view, i);
  return veil;
}

#endif
