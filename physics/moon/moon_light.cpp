#include "physics/moon/moon_light.h"

#include "ephemeris/night_irradiance.h"
#include "physics/spectrum/spectral_data.h"
#include "physics/atmosphere/precompute/rec709_tables.h"
#include "physics/spectrum/spectrum.h"
#include "physics/atmosphere/physical_camera.h"
#include "physics/common/common_physics.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <vector>

namespace skyig::sky::night {

namespace {

// Rec.709 per lux of sunlight reflected with a relative reflectance 1 + slope (lambda - 550 nm).
glm::dvec3 reflectedColour(double slopePerNm) {
  std::vector<double> wavelengths;
  for (double w = 365.0; w <= 825.0; w += 10.0) wavelengths.push_back(w);
  const atmosphere::SpectralConverter converter(wavelengths);
  std::vector<double> spectrum;
  for (double w : wavelengths) spectrum.push_back(atmosphere::solarIrradiance(w) * std::max(0.0, 1.0 + slopePerNm * (w - 550.0)));
  const glm::dvec3 xyz = converter.toXyz(spectrum);
  return atmosphere::xyzToRec709(xyz) / xyz.y;
}

}  // namespace

const glm::dvec3& moonlightColour() {
  // 1 - 110 nm x slope = 10^(-0.4 (0.92 - 0.65)): the moon's B (440 nm) to V (550 nm) excess.
  static const glm::dvec3 colour = reflectedColour(kMoonReflectanceSlopePerNm);
  return colour;
}

double moonReflectanceRelative(double wavelengthNm) {
  return std::max(0.0, 1.0 + kMoonReflectanceSlopePerNm * (wavelengthNm - 550.0));
}

const glm::dvec3& sunlightColour() {
  static const glm::dvec3 colour = reflectedColour(0.0);
  return colour;
}

double sunMoonDistanceKm(const ephemeris::SkyEphemeris& sky) {
  const ephemeris::Vec3 sun = sky.sun.distanceKm * sky.sun.enu;
  const ephemeris::Vec3 moon = sky.moon.distanceKm * sky.moon.enu;
  return ephemeris::norm(sun - moon);
}

glm::dvec3 moonlightScale(const ephemeris::SkyEphemeris& sky) {
  const double ratio = ephemeris::moonIrradiance(sky.moon.phaseAngleRad, sky.moon.distanceKm, sunMoonDistanceKm(sky)) /
                       ephemeris::kSolarConstantWm2;
  return ratio * moonlightColour() / sunlightColour();
}

MoonRadiance moonlitSkyRadiance(const atmosphere::AtmosphereModel& model, double heightM,
                                const glm::dvec3& moonDirection, const glm::dvec3& scale,
                                const glm::dvec3& viewEnu) {
  if (scale == glm::dvec3(0.0)) return {};
  const glm::dvec3 rgb = atmosphere::moonlitSkyRec709(model, atmosphere::physicalCamera(model, heightM),
                                                     glm::normalize(viewEnu), moonDirection, scale);
  return {rgb, shader::rec709Luminance(rgb)};
}

}  // namespace skyig::sky::night
