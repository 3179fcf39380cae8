#include "physics/weather/fog_layer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace skyig::weather {

namespace {

constexpr double kKoschmieder = sky::kKoschmiederConstant;

[[noreturn]] void bad(const char* name, double value, const char* expected) {
  char text[160];
  std::snprintf(text, sizeof text, "fog layer: %s = %g is invalid (expected %s)", name, value, expected);
  throw std::invalid_argument(text);
}


}  // namespace

double tablesVisibilityKm(double visibilityKm) { return std::max(visibilityKm, kTablesVisibilityKm); }

sky::FogSpec hazeBelowTables(double visibilityKm, double scaleHeightM) {
  if (!(visibilityKm > 0.0) || visibilityKm >= kTablesVisibilityKm) return {};
  const double extinctionPerKm = kKoschmieder / visibilityKm - kKoschmieder / kTablesVisibilityKm;
  return {0.0, scaleHeightM, kKoschmieder / extinctionPerKm};
}

void validate(const sky::FogSpec& s) {
  if (!(s.visibilityKm >= 0.0) || !std::isfinite(s.visibilityKm)) bad("visibility_km", s.visibilityKm, "0 (none) or more");
  if (s.visibilityKm == 0.0) return;
  if (!(s.bottomM >= 0.0) || !std::isfinite(s.bottomM)) bad("bottom_m", s.bottomM, "0 or more, above the ground");
  if (!(s.topM > s.bottomM) || !std::isfinite(s.topM)) bad("top_m", s.topM, "above the bottom");
  if (!(s.asymmetry >= 0.0 && s.asymmetry < 1.0)) bad("asymmetry", s.asymmetry, "in [0, 1)");
  for (double a : s.albedo)
    if (!(a > 0.0 && a <= 1.0)) bad("albedo", a, "in (0, 1]");
  if (!(s.transitionM >= 0.0) || !std::isfinite(s.transitionM)) bad("transition_m", s.transitionM, "0 (a hard edge) or more");
  if (s.bottomTransitionM && (!(*s.bottomTransitionM >= 0.0) || !std::isfinite(*s.bottomTransitionM)))
    bad("bottom transition", *s.bottomTransitionM, "0 (a hard edge) or more");
}

FogLayer makeFogLayer(const sky::FogSpec& spec, double planetRadiusM, double groundAlbedo,
                      const glm::dvec3& topIrradiance) {
  validate(spec);
  FogLayer f{};
  f.planet_radius = planetRadiusM;
  f.bottom_height = spec.bottomM;
  f.top_height = spec.topM;
  f.extinction = spec.visibilityKm > 0.0 ? kKoschmieder / (spec.visibilityKm * 1000.0) : 0.0;
  f.asymmetry = spec.asymmetry;
  f.albedo = glm::dvec3(spec.albedo[0], spec.albedo[1], spec.albedo[2]);
  f.ground_albedo = groundAlbedo;
  f.top_irradiance = topIrradiance;
  f.band_height = spec.transitionM;
  f.bottom_band_height = spec.bottomTransitionM.value_or(spec.transitionM);
  return f;
}

double throughFogLuminance(const FogLayer& fog, double behindCdM2, double h, double mu, double d) {
  return behindCdM2 * shader::fogTransmittance(fog, h, mu, d) +
         shader::rec709Luminance(shader::throughFog(fog, glm::dvec3(0.0), h, mu, d));
}

}  // namespace skyig::weather
