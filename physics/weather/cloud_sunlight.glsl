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

// Reflected by a layer of optical depth tau: the beam enters the face the eye sees at cosine mu0
// to its normal, the eye sees it at mu (both positive):
//   I / E = p(theta) mu0 / (mu0 + mu) [1 - exp(-tau (1 / mu0 + 1 / mu))].
Float cloudSingleReflected(Float tau, Float g, Float mu0, Float mu, Float cos_theta) {
  return cloudPhase(g, cos_theta) * mu0 / (mu0 + mu) * (1.0 - exp(-tau * (1.0 / mu0 + 1.0 / mu)));
}

// Transmitted through it, the beam entering the far face at mu0, the eye seeing the near one at mu:
//   I / E = p(theta) mu0 / (mu0 - mu) [exp(-tau / mu0) - exp(-tau / mu)], which tends to
//   p(theta) tau / mu exp(-tau / mu) as mu tends to mu0.
Float cloudSingleTransmitted(Float tau, Float g, Float mu0, Float mu, Float cos_theta) {
  Float p = cloudPhase(g, cos_theta);
  if (abs(mu0 - mu) < 1e-4) return p * tau / mu * exp(-tau / mu);
  return p * mu0 / (mu0 - mu) * (exp(-tau / mu0) - exp(-tau / mu));
}

#endif
