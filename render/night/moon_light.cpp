#include "render/night/moon_light.h"

#include "ephemeris/night_irradiance.h"
#include "render/atmosphere/spectral_data.h"
#include "render/atmosphere/spectrum.h"
#include "render/sky_state.h"
#include "shaders/physics.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <vector>

namespace skyig::render {

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
  static const glm::dvec3 colour = reflectedColour(0.0020);
  return colour;
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

MoonRadiance moonlitSkyRadiance(const atmosphere::AtmosphereModel& model, const SkyState& state,
                                const glm::dvec3& viewEnu) {
  if (state.moonlightScale == glm::dvec3(0.0)) return {};
  // The observer as the sky pass places it (render/physical_sky_pass.h physicalCamera).
  const glm::dvec3 camera(0.0, 0.0, model.parameters(0).bottom_radius + std::max(state.observer.heightM, 1.0));
  const glm::dvec3 rgb =
      model.converter().toRec709(model.skyRadiance(camera, glm::normalize(viewEnu), state.moonDirection)) *
      state.moonlightScale;
  return {rgb, shader::rec709Luminance(rgb)};
}

}  // namespace skyig::render
