#ifndef SKYIG_STARS_STAR_PSF_GLSL
#define SKYIG_STARS_STAR_PSF_GLSL
// Point sources (stars, planets) on screen, written once for the GPU pass and the CPU tests.
// A star is far smaller than a pixel: what the eye gets from it is its illuminance E (lux), not
// a radiance. The pass spreads E over a few pixels with a normalised Gaussian point-spread
// function and divides by each pixel's solid angle, so that sum(radiance x pixel solid angle)
// = E at any resolution and field of view (docs/night-sky-stars.md).

// The HDR pass's PSF, its standard deviation in pixels: integrated over each pixel
// (starPsfPixelWeight) it sums to 1 at any width; its truncation at kStarPsfRadiusSigmas loses
// exp(-8) = 3e-4: no per-star normalisation is needed.
const Float kStarPsfSigmaPx = 1.0;
const Float kStarPsfRadiusSigmas = 4.0;

// Weight of the pixel whose centre is `offsetPx` from the star's image, the Gaussian sampled at
// the pixel's centre: sums to 1 within exp(-2 pi^2 sigma^2) (Poisson summation) for sigma >= 0.7
// px only; a narrower PSF falls between the centres (starPsfPixelWeight does not).
Float starPsfWeight(IN(vec2) offsetPx, Float sigmaPx) {
  Float r2 = dot(offsetPx, offsetPx);
  if (r2 > kStarPsfRadiusSigmas * kStarPsfRadiusSigmas * sigmaPx * sigmaPx) return 0.0;
  return exp(-0.5 * r2 / (sigmaPx * sigmaPx)) / (2.0 * 3.14159265358979 * sigmaPx * sigmaPx);
}

// The error function, Abramowitz & Stegun (1964) 7.1.26: |error| < 1.5e-7.
Float starErf(Float x) {
  Float t = 1.0 / (1.0 + 0.3275911 * abs(x));
  Float poly = t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
  Float e = 1.0 - poly * exp(-x * x);
  return x < 0.0 ? -e : e;
}

// The share of a Gaussian of `sigmaPx` centred `offsetPx` from a pixel's centre that falls in
// that pixel (one axis): the PSF integrated over the pixel, not sampled at its centre, so a
// star narrower than a pixel still lands with all its light, wherever it sits in the pixel.
Float starPsfPixelShare(Float offsetPx, Float sigmaPx) {
  Float k = 1.0 / (sigmaPx * 1.41421356237);
  return 0.5 * (starErf((offsetPx + 0.5) * k) - starErf((offsetPx - 0.5) * k));
}

// Weight of the pixel whose centre is `offsetPx` from the star's image, integrated over the
// pixel: sums to 1 at any width (the truncation at kStarPsfRadiusSigmas, plus the pixel's
// half-diagonal, loses < 1e-3).
Float starPsfPixelWeight(IN(vec2) offsetPx, Float sigmaPx) {
  Float cut = kStarPsfRadiusSigmas * sigmaPx + 0.7072;
  if (dot(offsetPx, offsetPx) > cut * cut) return 0.0;
  return starPsfPixelShare(offsetPx.x, sigmaPx) * starPsfPixelShare(offsetPx.y, sigmaPx);
}

// The brightest pixel's weight for a star at the worst place, a pixel's corner (the four
// pixels around it share it equally): (erf(1 / (sigma sqrt 2)) / 2)^2, from 1/4 for a star far
// narrower than a pixel down to exp(-1 / (4 sigma^2)) / (2 pi sigma^2) for a wide one.
Float starPsfCornerPeakWeight(Float sigmaPx) {
  Float s = starPsfPixelShare(0.5, sigmaPx);
  return s * s;
}

// The solid angle (sr) over which a star's light makes its brightest pixel at the worst place:
// the pixel's over the brightest pixel's share; about 2 pi sigma^2 on a fine channel, 4 pixels
// on a coarse one. The display's threshold for points is set on it
// (physics/eye/point_source_visibility.glsl, displayedThresholdLux).
Float starPsfPeakSolidAngle(Float pixelSr, Float sigmaPx) { return pixelSr / starPsfCornerPeakWeight(sigmaPx); }

// Half the side of the quad that holds every pixel starPsfPixelWeight reaches.
Float starPsfQuadHalfSizePx(Float sigmaPx) { return kStarPsfRadiusSigmas * sigmaPx + 1.25; }

// Solid angle (sr) of a pixel of `pixelNdcArea` (= 4 / (width height)) at NDC point `ndc` of a
// pinhole channel whose view ray is ndcToWorld * (x, y, 1): the Jacobian of the map from the
// plane z = 1 to directions, d(Omega) = |det M| dx dy / |M (x, y, 1)|^3.
Float pixelSolidAngle(IN(mat3) ndcToWorldMatrix, IN(vec2) ndc, Float pixelNdcArea) {
  vec3 ray = ndcToWorldMatrix * vec3(ndc, 1.0);
  Float len = length(ray);
  return abs(determinant(ndcToWorldMatrix)) * pixelNdcArea / (len * len * len);
}

#endif
