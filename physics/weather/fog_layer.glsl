#ifndef SKYIG_WEATHER_FOG_LAYER_GLSL
#define SKYIG_WEATHER_FOG_LAYER_GLSL
// A layer of fog, mist, precipitation or dust over the clear-air sky: a homogeneous slab of
// particles between two spheres about the planet's centre, grey in extinction (particles far
// larger than the wavelength), lit from its top by the sun and the sky the clear-air tables give
// there. Its light is the two-stream solution for diffuse light (Bohren 1987, "Multiple
// scattering of light and some of its observable consequences", Am. J. Phys. 55(6), 524-533):
// without absorption (water) R = (1 - g) tau / (2 + (1 - g) tau), T = 1 - R, the up and down
// fluxes linear in the optical depth inside, over a Lambertian ground (adding the ground's
// reflections: R + T^2 a / (1 - R a)); with absorption (dust, sand: an albedo per channel below
// 1, which tints the layer) the same equations' hyperbolic solution. Closed forms, so a new layer
// costs no table and shows the frame after the host sends it. physics/weather/fog_layer.h derives
// a layer from the host's weather; the sky pass and the CPU (the eye's adaptation) compose with
// throughFog.
#include "physics/common/constants.glsl"
#include "physics/weather/fog_layer_parameters.glsl"

// Length of the part of [0, d] of the ray from height h (above a sphere of radius R) with cosine
// mu to the vertical that lies below height h_s: between the roots of t^2 + 2 r mu t + r^2 - r_s^2
// (r = R + h, r_s = R + h_s), taken as q and c / q with c = (h - h_s)(2R + h + h_s): neither
// cancels in single precision near the planet's radius.
Float chordBelowHeight(Float R, Float h, Float mu, Float d, Float h_s) {
  Float b = (R + h) * mu;
  Float c = (h - h_s) * (2.0 * R + h + h_s);
  Float discriminant = b * b - c;
  if (discriminant <= 0.0) return 0.0;
  Float q = -(b + (b >= 0.0 ? 1.0 : -1.0) * sqrt(discriminant));
  Float t0 = q;
  Float t1 = q != 0.0 ? c / q : 0.0;
  return max(min(max(t0, t1), d) - max(min(t0, t1), 0.0), 0.0);
}

// Metres of the ray's first d metres inside the layer, from height h. A layer on the ground (most
// are) has nothing below it on a ray that ends at the ground: its bottom's chord is skipped.
Float fogPathLength(IN(FogLayer) fog, Float h, Float mu, Float d) {
  Float below = fog.bottom_height > 0.0 ? chordBelowHeight(fog.planet_radius, h, mu, d, fog.bottom_height) : 0.0;
  return max(chordBelowHeight(fog.planet_radius, h, mu, d, fog.top_height) - below, 0.0);
}

// Bohren 1987 (two-stream, no absorption): the slab's reflectance.
Float fogSlabReflectance(Float tau, Float g) {
  Float x = (1.0 - g) * tau;
  return x / (2.0 + x);
}

// Down- and upward flux over the irradiance at the top, at optical depth tau_in below the top of
// a slab of depth tau over a ground of albedo a: linear between the slab's ends, 1 and
// R + T a T' down from the top, T' = T / (1 - R a) and a T' at the bottom.
vec2 fogFluxes(Float tau_in, Float tau, Float g, Float a) {
  Float r = fogSlabReflectance(tau, g);
  Float down_bottom = (1.0 - r) / (1.0 - r * a);
  Float up_top = r + (1.0 - r) * a * down_bottom;
  Float s = tau > 0.0 ? clamp(tau_in / tau, 0.0, 1.0) : 0.0;
  return vec2(mix(1.0, down_bottom, s), mix(up_top, a * down_bottom, s));
}

// Bohren's two-stream equations with absorption, for the backscattered fraction b = (1 - g) / 2
// and single-scattering albedo omega, tau counted down from the top:
//   dF_down/dtau = -alpha F_down + beta F_up,  dF_up/dtau = -beta F_down + alpha F_up,
//   alpha = 1 - omega (1 - b),  beta = omega b,  k^2 = alpha^2 - beta^2.
// From the bottom (F_up = a D, F_down = D) up by u = tau - tau_in the solution is
// exp(-M u) = cosh(k u) - sinh(k u) / k M, and F_down = 1 at the top fixes D:
//   F_down = [cosh(k u) + sinh(k u) / k (alpha - beta a)] / [cosh(k tau) + sinh(k tau) / k (alpha - beta a)]
//   F_up   = [a cosh(k u) + sinh(k u) / k (beta - alpha a)] / (the same).
// Written with exponentials that never overflow (numerator and denominator over cosh(k tau)).
// omega = 1 (k = 0) is fogFluxes' linear solution, the limit of this one.
vec2 fogFluxesAbsorbing(Float tau_in, Float tau, Float g, Float a, Float omega) {
  Float b = 0.5 * (1.0 - g);
  Float alpha = 1.0 - omega * (1.0 - b);
  Float beta = omega * b;
  Float k = sqrt(max(alpha * alpha - beta * beta, 1e-12));
  Float u = clamp(tau - tau_in, 0.0, tau);
  Float p = exp(k * (u - tau));
  Float m = exp(-k * (u + tau));
  Float e2 = exp(-2.0 * k * tau);
  Float c = alpha - beta * a;
  Float denominator = (1.0 + e2) + c * (1.0 - e2) / k;
  return vec2((p + m) + c * (p - m) / k, a * (p + m) + (beta - alpha * a) * (p - m) / k) / denominator;
}

// Below this albedo the layer absorbs (fogFluxesAbsorbing); at or above it, it is taken as water
// (fogFluxes), where the hyperbolic form's 1 / k would lose single precision.
const Float kFogConservativeAlbedo = 0.999;

// The layer's radiance at the depth of an eye h metres above the ground (its top seen from
// above, its bottom from below): the downward flux seen looking up, the upward looking down, each
// a Lambertian field (radiance = flux / pi).
FogEye fogEye(IN(FogLayer) fog, Float h) {
  Float tau = fog.extinction * (fog.top_height - fog.bottom_height);
  Float tau_in = fog.extinction * (fog.top_height - clamp(h, fog.bottom_height, fog.top_height));
  vec3 down = vec3(0.0);
  vec3 up = vec3(0.0);
  for (int i = 0; i < 3; ++i) {
    vec2 f = fog.albedo[i] >= kFogConservativeAlbedo
                 ? fogFluxes(tau_in, tau, fog.asymmetry, fog.ground_albedo)
                 : fogFluxesAbsorbing(tau_in, tau, fog.asymmetry, fog.ground_albedo, fog.albedo[i]);
    down[i] = f.x;
    up[i] = f.y;
  }
  FogEye eye;
  eye.looking_up = fog.top_irradiance * down / PI;
  eye.looking_down = fog.top_irradiance * up / PI;
  return eye;
}

// Along a view of cosine mu_view to the vertical (up positive): the two mixed by the cosine.
vec3 fogRadiance(IN(FogEye) eye, Float mu_view) {
  Float up = 0.5 * (1.0 + mu_view);
  return up * eye.looking_up + (1.0 - up) * eye.looking_down;
}

// throughFog with the eye's radiance already solved (fogEye at h): one solve for the many views of
// one eye (the sky pass's table, fog_table.h).
vec3 throughFogSeen(IN(FogLayer) fog, IN(FogEye) eye, IN(vec3) behind, Float h, Float mu, Float d) {
  Float t = exp(-fog.extinction * fogPathLength(fog, h, mu, d));
  return behind * t + fogRadiance(eye, mu) * (1.0 - t);
}

// What the eye at height h sees along a view of cosine mu where the clear air shows `behind` and
// the ray ends d metres on (the ground, or the top of the atmosphere): the fog on the way dims it
// by exp(-extinction s) and adds its own light times 1 - exp(-extinction s), its radiance taken at
// the eye's depth in it (its top seen from above, its bottom from below), so a climb through the
// top is seamless.
vec3 throughFog(IN(FogLayer) fog, IN(vec3) behind, Float h, Float mu, Float d) {
  if (fog.extinction <= 0.0) return behind;
  return throughFogSeen(fog, fogEye(fog, h), behind, h, mu, d);
}

// The fog's transmittance along a ray (the sun's light to the eye, a surface's to the eye).
Float fogTransmittance(IN(FogLayer) fog, Float h, Float mu, Float d) {
  return fog.extinction > 0.0 ? exp(-fog.extinction * fogPathLength(fog, h, mu, d)) : 1.0;
}

#endif
