#ifndef SKYIG_COMMON_DITHER_GLSL
#define SKYIG_COMMON_DITHER_GLSL
// The dither of the 8-bit outputs (the tone pass, the warp-and-blend pass): triangular, +-1 LSB
// at amplitude 1, so dark gradients do not band; a hash of the pixel, so frames are
// deterministic. GPU only (it uses swizzles and fract of vectors).

float hash12(vec2 p) {  // Hoskins, "Hash without sine" (2014), hash12
  vec3 p3 = fract(vec3(p.xyx) * 0.1031);
  p3 += dot(p3, p3.yzx + 33.33);
  return fract((p3.x + p3.y) * p3.z);
}

// The dither to add to a value in [0, 1] before it is written to 8 bits, at this fragment.
float ditherLsb(vec2 fragCoord, float amplitudeLsb) {
  return (hash12(fragCoord) + hash12(fragCoord + 71.7) - 1.0) * amplitudeLsb / 255.0;
}

#endif
