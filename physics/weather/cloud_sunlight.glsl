#ifndef SKYIG_WEATHER_CLOUD_SUNLIGHT_GLSL
#define SKYIG_WEATHER_CLOUD_SUNLIGHT_GLSL
// The sunlight (or moonlight) a cloud deck scatters once towards the eye, on top of its diffuse
// light (fog_layer.glsl's two-stream, which holds the view's cosine but not the sun's direction):
// what makes a thin veil's aureole round the sun, the glare of a sea of cloud towards a low sun,
// and a base lit red from below by a sun under the deck's own horizon. The single-scattering
// solutions of a plane-parallel layer lit by a collimated beam (Chandrasekhar 1950, Radiative
// Transfer, ch. I.3; Hansen & Travis 1974, Space Sci. Rev. 16, eqs. 2.18-2.19), per unit
// irradiance normal to the beam, with the Henyey-Greenstein phase function (1941).
#include "physics/common/constants.glsl"

// Henyey & Greenstein 1941, normalised to 1 over the sphere (per steradian).
Float cloudPhase(Float g, Float cos_theta) {
  Float d = 1.0 + g * g - 2.0 * g * cos_theta;
  return (1.0 - g * g) / (4.0 * PI * d * sqrt(d));
}

// A layer of optical depth tau seen at cosine mu (> 0) to the normal of the face the eye sees,
// the beam at cosine mu0 to it: mu0 > 0 lights that face, and the layer reflects
//   I / E = p(theta) mu0 / (mu0 + mu) [1 - exp(-tau (1 / mu0 + 1 / mu))];
// mu0 < 0 lights the far face (entering it at a = -mu0), and the layer transmits
//   I / E = p(theta) a / (a - mu) [exp(-tau / a) - exp(-tau / mu)],
// which tends to p(theta) tau / mu exp(-tau / mu) as a tends to mu. Both from the same two
// exponentials (llvmpipe runs both sides of a branch).
Float cloudSingleScattered(Float tau, Float g, Float mu0, Float mu, Float cos_theta) {
  Float a = abs(mu0);
  Float e0 = exp(-tau / a);
  Float e1 = exp(-tau / mu);
  Float reflected = a / (a + mu) * (1.0 - e0 * e1);
  Float transmitted = abs(a - mu) < 1e-4 ? tau / mu * e1 : a / (a - mu) * (e0 - e1);
  return cloudPhase(g, cos_theta) * (mu0 > 0.0 ? reflected : transmitted);
}

#endif
