#ifndef SKYIG_NIGHT_MOON_GLSL
#define SKYIG_NIGHT_MOON_GLSL
// The moon's disc (docs/night-sky.md "Moon"): a sphere lit by the sun and by the
// earth, seen through refraction and extinction. Shared by the GL pass (render/passes/night/moon.*)
// and the CPU (physics/moon/moon_disc.h) through physics/moon/moon_physics.h.
//
// Reflectance: Lommel-Seeliger, r = mu0 / (mu0 + mu), the single-scattering limit of Hapke's
// (1981, eq. 16) law for a dark surface; it gives the full moon its flat, unshaded look. Its
// disc integral over a sphere is the phase law of eq. 9 of Wang, Ji & Zhang 2011 (after Jensen
// et al. 2001; corrected: ln cot(phi/4), printed with cos),
// int mu0 mu / (mu0 + mu) dA = pi/2 (1 - sin(phi/2) tan(phi/2) ln cot(phi/4)), so with
// radiance L = 4 C_a / (3 pi) E_sun r the disc's irradiance is eq. 9 exactly (the tests
// integrate it numerically). Hapke's opposition surge B(g) is a factor of the phase angle
// alone: it would change the total only, which eq. 9 fixes, so it is left out (B = 1).
#include "physics/common/constants.glsl"
#include "physics/common/refraction.glsl"

// C_a of eq. 9 (Jensen et al. 2001) and the radiance coefficient 4 C_a / (3 pi) that makes
// the Lommel-Seeliger disc integral equal eq. 9.
const Float MOON_ALBEDO_CA = 0.072;
const Float MOON_RADIANCE_COEFFICIENT = 4.0 * MOON_ALBEDO_CA / (3.0 * PI);

Float lommelSeeliger(Float mu0, Float mu) {
  if (mu0 <= 0.0 || mu <= 0.0) return 0.0;
  return mu0 / (mu0 + mu);
}

// Where a view falls on the disc: its offset from the centre in the plane of the sky, in units
// of the disc's radius (|q| < 1 on the disc). Orthographic: the perspective error is of order
// the angular radius squared, 2e-5.
vec3 moonDiscOffset(IN(vec3) view, IN(vec3) centre, Float sinRadius) {
  return (view - dot(view, centre) * centre) / sinRadius;
}

// Outward normal of the visible hemisphere under offset q (clamped to the limb).
vec3 moonSurfaceNormal(IN(vec3) q, IN(vec3) centre) {
  Float s2 = min(dot(q, q), 1.0);
  return q - sqrt(1.0 - s2) * centre;
}

// Texture coordinates in the selenographic equirectangular map (physics/moon/data/moon.png):
// longitude 0 (the mean sub-earth point) at u = 0.5, east longitude towards +u, north at v = 0
// (the first image row). `north` and `east` are the moon's axes in the observer's frame.
vec2 selenographicUv(IN(vec3) n, IN(vec3) towardObserver, IN(vec3) north, IN(vec3) east) {
  Float lon = atan(dot(n, east), dot(n, towardObserver));
  Float lat = asin(clamp(dot(n, north), -1.0, 1.0));
  return vec2(0.5 + lon / (2.0 * PI), 0.5 - lat / PI);
}

// Radiance of a surface point of relative albedo `albedo` (mean 1 over the near side): sunlight
// by Lommel-Seeliger, plus earthshine, which comes from the observer's direction (mu0 = mu,
// r = 1/2). The scales carry the irradiances, the lunar colour and the normalisation.
vec3 moonSurfaceRadiance(IN(vec3) n, IN(vec3) towardObserver, IN(vec3) towardSun, Float albedo,
                         IN(vec3) sunlitScale, IN(vec3) earthshineScale) {
  Float mu = dot(n, towardObserver);
  Float earthshine = mu > 0.0 ? 0.5 : 0.0;
  return albedo * (sunlitScale * lommelSeeliger(dot(n, towardSun), mu) + earthshineScale * earthshine);
}

// Fraction of a pixel of angular size `pixel` inside the limb, `inside` radians within it:
// a one-pixel ramp centred on the limb, which keeps the disc's area (and energy) to first order.
Float moonLimbCoverage(Float inside, Float pixel) { return clamp(inside / max(pixel, 1e-9) + 0.5, 0.0, 1.0); }

// Texture coordinate of an elevation in an ExtinctionProfile's table
// (physics/atmosphere/extinction_profile.h): u = (1 + sign(e) sqrt(|e| / 90 deg)) / 2.
Float extinctionCoordinate(Float elevation) {
  Float e = clamp(elevation, -0.5 * PI, 0.5 * PI);
  return 0.5 * (1.0 + sign(e) * sqrt(abs(e) / (0.5 * PI)));
}

#endif
