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

// The transition band (CIGI Weather Control): above the top (and below a raised bottom) the
// extinction falls linearly to none over band_height metres (bottom_band_height below the
// bottom). Along the ray x(t) the height under a level h_s is, to first order,
// q(t) = (r_s^2 - |x(t)|^2) / 2 r_s = a - b t - k t^2 (exact but for a factor 1 - (h_s - h) /
// 2 r_s: 1e-4 at 1.3 km), a concave quadratic in t, so the integral of max(q - c, 0) over [0, d]
// has a closed form: between the roots of q = c, taken as chordBelowHeight takes them, as
// (t1 - t0)(a - b (t0 + t1) / 2 - k (t0^2 + t0 t1 + t1^2) / 3).
Float depthBelowIntegral(Float R, Float h, Float mu, Float d, Float h_s, Float c) {
  Float r_s = R + h_s;
  Float a = (h_s - h) * (2.0 * R + h_s + h) / (2.0 * r_s) - c;
  Float b = (R + h) * mu / r_s;
  Float k = 0.5 / r_s;
  Float discriminant = b * b + 4.0 * k * a;
  if (discriminant <= 0.0) return 0.0;
  Float q = -0.5 * (b + (b >= 0.0 ? 1.0 : -1.0) * sqrt(discriminant));
  Float t0 = q / k;
  Float t1 = q != 0.0 ? -a / q : 0.0;
  Float lo = max(min(t0, t1), 0.0);
  Float hi = min(max(t0, t1), d);
  if (hi <= lo) return 0.0;
  return (hi - lo) * (a - 0.5 * b * (lo + hi) - k * (lo * lo + lo * hi + hi * hi) / 3.0);
}

// Metres of the ray's first d metres under a ramp whose extinction grows from none at height
// ramp_top to the layer's over `band` metres below it, each metre counted by its share: the
// integral of clamp(q / band, 0, 1). A hard edge (band 0) is chordBelowHeight.
Float chordBelowRamp(Float R, Float h, Float mu, Float d, Float ramp_top, Float band) {
  if (band <= 0.0) return chordBelowHeight(R, h, mu, d, ramp_top);
  return (depthBelowIntegral(R, h, mu, d, ramp_top, 0.0) - depthBelowIntegral(R, h, mu, d, ramp_top, band)) / band;
}

// The band below the bottom: no deeper than the bottom's height (it stops at the ground).
Float fogBottomBand(IN(FogLayer) fog) { return min(fog.bottom_band_height, fog.bottom_height); }

// Metres of the ray's first d metres inside the layer, from height h, a metre of its bands
// counted by its share of the layer's extinction. A layer on the ground (most are) has nothing
// below it on a ray that ends at the ground: its bottom's chord is skipped.
Float fogPathLength(IN(FogLayer) fog, Float h, Float mu, Float d) {
  Float R = fog.planet_radius;
  Float below = fog.bottom_height > 0.0 ? chordBelowRamp(R, h, mu, d, fog.bottom_height, fogBottomBand(fog)) : 0.0;
  return max(chordBelowRamp(R, h, mu, d, fog.top_height + fog.band_height, fog.band_height) - below, 0.0);
}

// The layer's vertical optical depth above height h (its bands' ramps integrated: (b - z)^2 / 2b
// for z metres into a band of b), and its whole column (fogColumnDepth).
Float fogDepthAbove(IN(FogLayer) fog, Float h) {
  Float b = fog.band_height;
  Float bb = fogBottomBand(fog);
  Float top_band = b > 0.0 ? 0.5 * b : 0.0;
  if (h >= fog.top_height + b) return 0.0;
  if (h >= fog.top_height) return fog.extinction * (fog.top_height + b - h) * (fog.top_height + b - h) / (2.0 * b);
  Float above = fog.extinction * (top_band + fog.top_height - max(h, fog.bottom_height));
  if (h >= fog.bottom_height || bb <= 0.0) return above;
  Float z = min(fog.bottom_height - h, bb);  // metres down into the bottom band
  return above + fog.extinction * (z - 0.5 * z * z / bb);
}
Float fogColumnDepth(IN(FogLayer) fog) { return fogDepthAbove(fog, fog.bottom_height - fogBottomBand(fog)); }

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
// Bohren's two-stream equations are written in optical depth, so they hold for a layer whose
// extinction varies with height (its bands) with the depths counted through them.
FogEye fogEye(IN(FogLayer) fog, Float h) {
  Float tau = fogColumnDepth(fog);
  Float tau_in = fogDepthAbove(fog, h);
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
  // How deep the eye is, in the diffusion's own unit (the scaled optical depth (1 - g) tau) from
  // the nearer boundary: the boundary's law gives way to the field inside.
  eye.inside = 1.0 - exp(-(1.0 - fog.asymmetry) * min(tau_in, tau - tau_in));
  eye.limb_darkening = fog.limb_darkening;
  return eye;
}

// The law a thick layer's boundary shines by, over the Lambertian's flux / pi: (1 + b mu) /
// (1 + 2 b / 3), the same flux (its integral of mu over the hemisphere is the Lambertian's).
Float fogLimbLaw(Float b, Float mu) { return (1.0 + b * mu) / (1.0 + 2.0 * b / 3.0); }

// Along a view of cosine mu_view to the vertical (up positive): the two mixed by the cosine,
// the field inside the layer. A deck's (limb darkening b > 0) boundary seen from outside shines
// by fogLimbLaw instead, its base with the downward flux and its top with the upward one (Moon &
// Spencer 1942: an overcast sky's L / L_z = (1 + 2 cos Z) / 3), and the eye going in passes from
// the one to the other with its depth (FogEye.inside), so a climb through a base shows no step.
vec3 fogRadiance(IN(FogEye) eye, Float mu_view) {
  Float up = 0.5 * (1.0 + mu_view);
  vec3 field = up * eye.looking_up + (1.0 - up) * eye.looking_down;
  if (eye.limb_darkening <= 0.0) return field;
  vec3 boundary = mu_view >= 0.0 ? eye.looking_up * fogLimbLaw(eye.limb_darkening, mu_view)
                                 : eye.looking_down * fogLimbLaw(eye.limb_darkening, -mu_view);
  return mix(boundary, field, eye.inside);
}

// throughFog with the eye's radiance already solved (fogEye at h): one solve for the many views of
// one eye (the sky pass's table, fog_table.h).
// A deck with gaps (gap > 0) lets that share of what lies behind through untouched: the expected
// light over its field.
vec3 throughFogSeen(IN(FogLayer) fog, IN(FogEye) eye, IN(vec3) behind, Float h, Float mu, Float d) {
  Float t = mix(exp(-fog.extinction * fogPathLength(fog, h, mu, d)), 1.0, fog.gap);
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

// What a layer leaves of the light from above under it, over what reaches its top: the downward
// flux at its bottom (fogFluxes, the ground's reflections included), its gaps letting the rest
// through. Under a deck the ground and everything below it are lit by that share of its top's
// light (physics/weather/fog_table.h composes it).
Float fogShadeBelow(IN(FogLayer) fog) {
  if (fog.extinction <= 0.0) return 1.0;
  Float tau = fogColumnDepth(fog);
  return mix(fogFluxes(tau, tau, fog.asymmetry, fog.ground_albedo).x, 1.0, fog.gap);
}

// The fog's transmittance along a ray (the sun's light to the eye, a surface's to the eye).
Float fogTransmittance(IN(FogLayer) fog, Float h, Float mu, Float d) {
  return fog.extinction > 0.0 ? mix(exp(-fog.extinction * fogPathLength(fog, h, mu, d)), 1.0, fog.gap) : 1.0;
}

#endif
