#pragma once
// The colour and amount of moonlight, and the sky it lights (Jensen et al. 2001, section 4: the
// moon is a second light source of the atmosphere, scaled by its irradiance).
#include <glm/vec3.hpp>

#include "ephemeris/ephemeris.h"
#include "physics/atmosphere/model.h"
#include "physics/moon/moon_disc.h"

namespace skyig::sky::night {

// Linear Rec.709 of one lux of moonlight (luminance 1): sunlight (ASTM G-173) reflected with the
// moon's spectral reflectance, which rises by 0.2% per nm (relative to 550 nm), the slope that
// turns the sun's B-V = 0.65 into the moon's 0.92 (Allen's Astrophysical Quantities, 4th ed.,
// sections 14.7 and 12.3; the ROLO spectra of Kieffer & Stone 2005 rise alike).
const glm::dvec3& moonlightColour();
// The same for sunlight itself.
const glm::dvec3& sunlightColour();

// The moon's spectral reflectance above relative to its value at 550 nm: 1 + 0.002 (lambda -
// 550 nm), kept linear out to the goggles' 930 nm (sky/nvis), 1.76 there, as the ROLO
// reflectance spectra still rise steadily through the near infrared (Kieffer & Stone 2005, AJ
// 129, 2887).
inline constexpr double kMoonReflectanceSlopePerNm = 0.0020;
double moonReflectanceRelative(double wavelengthNm);

// Sun-moon distance (km) from the topocentric vectors.
double sunMoonDistanceKm(const ephemeris::SkyEphemeris& sky);

// Moon / sun irradiance above the atmosphere per Rec.709 channel, the sun taken at 1 au (the
// atmosphere's tables are lit by the 1 au sun): eq. 9 (with earthshine) over 1361 W/m^2, times
// the moonlight's colour relative to the sun's. Zero when the moon is new (phase law 0).
glm::dvec3 moonlightScale(const ephemeris::SkyEphemeris& sky);

// The sky lit by the moon along a view (ENU) for an observer at `heightM` above the model's
// ground: the model's sky radiance for a sun in the moon's (airless, ENU unit) direction, times
// moonlightScale (sky::SkyState holds both). Zero when the scale is.
MoonRadiance moonlitSkyRadiance(const atmosphere::AtmosphereModel& model, double heightM,
                                const glm::dvec3& moonDirection, const glm::dvec3& moonlightScale,
                                const glm::dvec3& viewEnu);

}  // namespace skyig::sky::night
