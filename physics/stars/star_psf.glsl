// Point sources (stars, planets) on screen, written once for the GPU pass and the CPU tests.
// A star is far smaller than a pixel: what the eye gets from it is its illuminance E (lux), not
// a radiance. The pass spreads E over a few pixels with a normalised Gaussian point-spread
// function and divides by each pixel's solid angle, so that sum(radiance x pixel solid angle)
// = E at any resolution and field of view (docs/night-sky-stars.md).

// The PSF's standard deviation in pixels. Sampled at pixel centres, a Gaussian of sigma >= 0.7
// px sums to 1 within exp(-2 pi^2 sigma^2) < 1e-4 (Poisson summation), and its truncation at
// kStarPsfRadiusSigmas loses exp(-8) = 3e-4: no per-star normalisation is needed.
const Float kStarPsfSigmaPx = 1.0;
const Float kStarPsfRadiusSigmas = 4.0;

// Weight of the pixel whose centre is `offsetPx` from the star's image, per pixel: sums to 1.
Float starPsfWeight(IN(vec2) offsetPx, Float sigmaPx) {
  Float r2 = dot(offsetPx, offsetPx);
  if (r2 > kStarPsfRadiusSigmas * kStarPsfRadiusSigmas * sigmaPx * sigmaPx) return 0.0;
  return exp(-0.5 * r2 / (sigmaPx * sigmaPx)) / (2.0 * 3.14159265358979 * sigmaPx * sigmaPx);
}

// Solid angle (sr) of a pixel of `pixelNdcArea` (= 4 / (width height)) at NDC point `ndc` of a
// pinhole channel whose view ray is ndcToWorld * (x, y, 1): the Jacobian of the map from the
// plane z = 1 to directions, d(Omega) = |det M| dx dy / |M (x, y, 1)|^3.
Float pixelSolidAngle(IN(mat3) ndcToWorldMatrix, IN(vec2) ndc, Float pixelNdcArea) {
  vec3 ray = ndcToWorldMatrix * vec3(ndc, 1.0);
  Float len = length(ray);
  return abs(determinant(ndcToWorldMatrix)) * pixelNdcArea / (len * len * len);
}
