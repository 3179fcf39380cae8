#ifndef SKYIG_NIGHT_AIRGLOW_GLSL
#define SKYIG_NIGHT_AIRGLOW_GLSL
// Airglow: a thin emitting layer near 90 km (the OI 557.7 nm green line peaks at 90-100 km),
// seen through a longer path towards the horizon. The van Rhijn (1921) factor for a layer at
// height h over a sphere of radius R, as Roach & Gordon (1973, "The Light of the Night Sky",
// ch. 3) and Leinert et al. (1998, airglow section) give it:
//   V(z) = 1 / sqrt(1 - (R / (R + h))^2 sin^2 z),
// 1 at the zenith, 6.0 at the horizon for h = 90 km.

const Float kAirglowLayerHeightM = 90.0e3;
const Float kAirglowEarthRadiusM = 6371.0e3;

Float vanRhijnFactor(Float cosZenith, Float earthRadiusM, Float layerHeightM) {
  Float ratio = earthRadiusM / (earthRadiusM + layerHeightM);
  Float sin2 = max(1.0 - cosZenith * cosZenith, 0.0);
  return 1.0 / sqrt(1.0 - ratio * ratio * sin2);
}

// Linear Rec.709 radiance (cd/m^2 per channel) above the lower atmosphere for a view with the
// given cosine of the zenith angle; zenithRec709 is the zenith's. Below the horizon the layer is
// still there, but the ground hides it: the caller's extinction (0 there) takes care of it.
vec3 airglowRadiance(IN(vec3) zenithRec709, Float cosZenith) {
  return zenithRec709 * vanRhijnFactor(max(cosZenith, 0.0), kAirglowEarthRadiusM, kAirglowLayerHeightM);
}

#endif
