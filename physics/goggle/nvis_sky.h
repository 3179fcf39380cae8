#pragma once
// The night's light sources in the goggles' band, from the same state as the eye's: each
// source's luminance (what skyig computes for the eye, after the state's extinction) beside its
// class A and class B NVIS radiance, through the same spectral transmittance
// (night_spectra.h). The probe's per-view components are in sky/night_probe.h
// (nightProbeLights); this file holds what they share and the irradiance on the ground.
#include <glm/vec3.hpp>

#include <memory>

#include "ephemeris/ephemeris.h"
#include "physics/atmosphere/extinction_profile.h"
#include "physics/stars/star_field.h"
#include "physics/goggle/night_spectra.h"

namespace skyig::sky::nvis {

// A luminance (cd/m^2) or illuminance (lux) beside its NVIS radiance (W m^-2 sr^-1) or
// irradiance (W m^-2).
struct NvisLight {
  double luminance = 0.0;
  NvisRadiance nvis;
  NvisLight& operator+=(const NvisLight& o) {
    luminance += o.luminance;
    nvis += o.nvis;
    return *this;
  }
};

// The spectral transmittance along an ENU view (normalised here) for `extinction`; unit
// transmittance without one (above the horizon; none below).
Transmittance transmittanceAlong(const atmosphere::ExtinctionProfile* extinction, const glm::dvec3& viewEnu);

// The sky scattered by the air from the moon and from the sun (rayleighScattered).
const Spectrum& moonlitSkySpectrum();
const Spectrum& sunlitSkySpectrum();

// One star or planet: its illuminance at the eye (lux, after extinction) and its NVIS
// irradiance (W m^-2), a blackbody of its temperature seen through the transmittance along it.
NvisLight pointSourceNvis(const night::PointSource& source, const atmosphere::ExtinctionProfile* extinction);

// The stars and planets within `coneRadiusRad` of `direction`, as a mean over the cone
// (physics/stars/star_luminance.h): cd/m^2 and W m^-2 sr^-1.
NvisLight pointSourcesNvis(const night::StarField& field, const atmosphere::ExtinctionProfile* extinction,
                           const glm::dvec3& direction, double coneRadiusRad);

// The moon's disc on a horizontal surface, `moonLux` after extinction (sky::moonIlluminanceLux),
// and its NVIS irradiance, the moon at the airless ENU `moonDirection`.
NvisLight moonIrradiance(double moonLux, const atmosphere::ExtinctionProfile* extinction, const glm::dvec3& moonDirection);

// The moonless night sky on a horizontal surface at the observer, by source: the airglow, the
// zodiacal light, the unresolved stars' floor (physics/night/night_diffuse.h
// nightDiffuseIlluminance, the same 8 x 16 directions) and the resolved stars and planets.
struct MoonlessSkyIrradiance {
  NvisLight airglow;
  NvisLight zodiacal;
  NvisLight integratedStarlight;
  NvisLight stars;
  NvisLight total() const;
};
// For the ephemeris' time and place, the extinction at the observer (null: none) and the state's
// stars and planets (null: none).
MoonlessSkyIrradiance moonlessSkyIrradiance(const ephemeris::SkyEphemeris& sky,
                                            std::shared_ptr<const atmosphere::ExtinctionProfile> extinction,
                                            const night::StarField* stars);

}  // namespace skyig::sky::nvis
