#ifndef SKYIG_COMMON_COLOR_GLSL
#define SKYIG_COMMON_COLOR_GLSL
// Colour spaces. skyig's HDR output is linear Rec.709 / sRGB primaries with a D65 white,
// scaled so that Y is the luminance in cd/m^2 (IEC 61966-2-1 matrices, Y row exact).
#include "physics/common/constants.glsl"

vec3 rec709ToXyz(IN(vec3) rgb) {
  return vec3(dot(vec3(0.4124564, 0.3575761, 0.1804375), rgb),
              dot(vec3(0.2126729, 0.7151522, 0.0721750), rgb),
              dot(vec3(0.0193339, 0.1191920, 0.9503041), rgb));
}

vec3 xyzToRec709(IN(vec3) xyz) {
  return vec3(dot(vec3(3.2404542, -1.5371385, -0.4985314), xyz),
              dot(vec3(-0.9692660, 1.8760108, 0.0415560), xyz),
              dot(vec3(0.0556434, -0.2040259, 1.0572252), xyz));
}

Float rec709Luminance(IN(vec3) rgb) { return dot(vec3(0.2126729, 0.7151522, 0.0721750), rgb); }

// (x, y, Y) to (X, Y, Z); a chromaticity with y = 0 carries no light.
vec3 xyYToXyz(IN(vec3) xyY) {
  Float safeY = max(xyY.y, 1e-9);
  return vec3(xyY.x * xyY.z / safeY, xyY.z, (1.0 - xyY.x - xyY.y) * xyY.z / safeY);
}

vec3 xyzToxyY(IN(vec3) xyz) {
  Float sum = xyz.x + xyz.y + xyz.z;
  if (sum <= 0.0) return vec3(0.3127, 0.3290, 0.0);  // black: D65 chromaticity, no light
  return vec3(xyz.x / sum, xyz.y / sum, xyz.y);
}

// Chromaticity of a Planckian radiator at temperature t (K), 1667-25000 K: cubic spline fit
// of Kang et al. 2002, "Design of advanced color temperature control system for HDTV
// applications", J. Korean Phys. Soc. 41(6), eq. 1-2.
vec2 planckianChromaticity(Float t) {
  Float k = clamp(t, 1667.0, 25000.0);
  Float k1 = 1e3 / k;
  Float k2 = k1 * k1;
  Float k3 = k2 * k1;
  Float x = k <= 4000.0 ? -0.2661239 * k3 - 0.2343589 * k2 + 0.8776956 * k1 + 0.179910
                        : -3.0258469 * k3 + 2.1070379 * k2 + 0.2226347 * k1 + 0.240390;
  Float x2 = x * x;
  Float x3 = x2 * x;
  Float y = k <= 2222.0   ? -1.1063814 * x3 - 1.34811020 * x2 + 2.18555832 * x - 0.20219683
            : k <= 4000.0 ? -0.9549476 * x3 - 1.37418593 * x2 + 2.09137015 * x - 0.16748867
                          : 3.0817580 * x3 - 5.87338670 * x2 + 3.75112997 * x - 0.37001483;
  return vec2(x, y);
}

#endif
