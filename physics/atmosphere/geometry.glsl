// Ray geometry in a spherically symmetric atmosphere. A ray starts at radius r with mu the
// cosine of its zenith angle; a point at distance d along it has radius
// r_d = sqrt(d^2 + 2 r mu d + r^2) (law of cosines, Bruneton & Neyret 2008, section 4).
#ifndef SKYIG_ATMOSPHERE_GEOMETRY_GLSL
#define SKYIG_ATMOSPHERE_GEOMETRY_GLSL
#include "physics/atmosphere/parameters.glsl"

Float atmClampCosine(Float mu) { return clamp(mu, -1.0, 1.0); }

Float atmClampDistance(Float d) { return max(d, 0.0); }

Float atmClampRadius(IN(AtmosphereParameters) atm, Float r) {
  return clamp(r, atm.bottom_radius, atm.top_radius);
}

// sqrt of a quantity that is >= 0 in exact arithmetic but may round below it.
Float atmSafeSqrt(Float a) { return sqrt(max(a, 0.0)); }

// Distance from radius r along mu to the top of the atmosphere (larger root of
// d^2 + 2 r mu d + r^2 = top^2).
Float distanceToTopAtmosphereBoundary(IN(AtmosphereParameters) atm, Float r, Float mu) {
  Float discriminant = r * r * (mu * mu - 1.0) + atm.top_radius * atm.top_radius;
  return atmClampDistance(-r * mu + atmSafeSqrt(discriminant));
}

// Distance to the ground (smaller root of d^2 + 2 r mu d + r^2 = bottom^2).
Float distanceToBottomAtmosphereBoundary(IN(AtmosphereParameters) atm, Float r, Float mu) {
  Float discriminant = r * r * (mu * mu - 1.0) + atm.bottom_radius * atm.bottom_radius;
  return atmClampDistance(-r * mu - atmSafeSqrt(discriminant));
}

bool rayIntersectsGround(IN(AtmosphereParameters) atm, Float r, Float mu) {
  return mu < 0.0 &&
         r * r * (mu * mu - 1.0) + atm.bottom_radius * atm.bottom_radius >= 0.0;
}

Float distanceToNearestAtmosphereBoundary(IN(AtmosphereParameters) atm, Float r, Float mu,
                                          bool ray_r_mu_intersects_ground) {
  if (ray_r_mu_intersects_ground) {
    return distanceToBottomAtmosphereBoundary(atm, r, mu);
  }
  return distanceToTopAtmosphereBoundary(atm, r, mu);
}

// Radius and cosines at distance d along the ray (r, mu), for a sun at mu_s and nu = v.s.
Float radiusAtDistance(IN(AtmosphereParameters) atm, Float r, Float mu, Float d) {
  return atmClampRadius(atm, sqrt(d * d + 2.0 * r * mu * d + r * r));
}

// Maps x in [0,1] to the centre of the first .. last texel of a table of `size` texels, so a
// lookup never extrapolates (Bruneton 2017, GetTextureCoordFromUnitRange).
Float textureCoordFromUnitRange(Float x, Float size) { return 0.5 / size + x * (1.0 - 1.0 / size); }

Float unitRangeFromTextureCoord(Float u, Float size) {
  return (u - 0.5 / size) / (1.0 - 1.0 / size);
}

// Integral over a step of length h of a positive function known at both ends, taken as
// exponential in between: h (b - a) / ln(b / a). Exact for the exponential density profiles,
// where the trapezoidal rule overestimates by (h/2H) coth(h/2H) - 1 (8% for a step of one
// Mie scale height, the step of 50 samples along a vertical ray). Falls back to the
// trapezoid where an end is zero or the ends are nearly equal.
Float exponentialStepIntegral(Float a, Float b, Float h) {
  if (a <= 0.0 || b <= 0.0 || abs(b - a) <= 1e-3 * a) {
    return 0.5 * (a + b) * h;
  }
  return h * (b - a) / log(b / a);
}

vec4 exponentialStepIntegral4(IN(vec4) a, IN(vec4) b, Float h) {
  return vec4(exponentialStepIntegral(a.x, b.x, h), exponentialStepIntegral(a.y, b.y, h),
              exponentialStepIntegral(a.z, b.z, h), exponentialStepIntegral(a.w, b.w, h));
}

#endif
