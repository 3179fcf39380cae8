#pragma once
// The bright sources whose light the eye scatters into a veil around them (the sun, the moon),
// as the display pass needs them: physics/eye/glare.glsl has the CIE 146:2002 veil per lux.
// Built with the SkyState on the worker, once per state.
#include <glm/vec3.hpp>

#include <array>

namespace skyig::sky::eye {

// The observer of the glare equation: a pilot of 30 (CIE 146's age factor 1 + (A/62.5)^4 is
// 1.05 at 30, 1.4 at 50) with brown eyes (pigmentation 0.5, the equation's middle value).
inline constexpr double kGlareObserverAgeYears = 30.0;
inline constexpr double kGlareOcularPigmentation = 0.5;

struct GlareSource {
  glm::dvec3 direction{0.0, 0.0, 1.0};  // apparent (refracted) ENU unit vector
  double angularRadiusRad = 0.0;
  glm::dvec3 rec709Lux{0.0};            // illuminance at the eye, facing the source, linear Rec.709 lux
};

// The sun and the moon, in that order; a source below the horizon or unlit has zero lux.
using GlareSources = std::array<GlareSource, 2>;

}  // namespace skyig::sky::eye
