#ifndef SKYIG_COMMON_REFRACTION_GLSL
#define SKYIG_COMMON_REFRACTION_GLSL
// A disc (the sun's, the moon's) seen through the air: refraction lifts a point seen at apparent
// altitude h by R(h) = r.y + r.z (h - r.x) + r.w (h - r.x)^2, the ephemeris' own refraction
// (Saemundsson, at the observer's pressure and temperature, ephemeris/refraction.h) expanded to
// second order about the disc's apparent centre r.x (ephemeris::refractionExpansion), so the
// disc sits where the ephemeris puts it and is flattened near the horizon as the real one is:
// its lower limb is lifted more than its upper. Over half a degree the third-order term is
// below 0.01 arcmin.

// The airless direction of a seen view (ENU: x east, y north, z up).
vec3 unrefractView(IN(vec3) view, IN(vec4) r) {
  Float horizontal = sqrt(view.x * view.x + view.y * view.y);
  if (horizontal < 1e-6) return view;
  Float h = asin(clamp(view.z, -1.0, 1.0));
  Float dh = h - r.x;
  Float airless = h - (r.y + r.z * dh + r.w * dh * dh);
  return vec3(view.x / horizontal * cos(airless), view.y / horizontal * cos(airless), sin(airless));
}

#endif
