#pragma once
// `skyig probe` at night (docs/night-sky.md): for a time and place, every view reports each light
// source separately and their sum, each as {"luminance_cd_m2", "rgb_cd_m2"} (linear Rec.709
// scaled so that Y is cd/m^2):
//   sunlit_sky      the physical atmosphere's sky lit by the sun (a copy of the day probe's "sky")
//   moonlit_sky     the same sky lit by the moon (Jensen et al. 2001)
//   moon            the moon's disc after extinction; present when the moon is known
//   stars_planets   the mean luminance of the stars and planets within 0.5 degrees of the view
//                   (sky/night/star_luminance.h), after extinction
//   milky_way       the Milky Way and the unresolved stars, after extinction
//   zodiacal_light  after extinction
//   airglow         after extinction
//   total           all the components, plus the day probe's "sun" disc and "ground" where the
//                   view has them
// With --irradiance, "irradiance" gains "moon_lux" (the disc, after extinction) and
// "moonlit_sky_lux" on a horizontal surface, beside the sun's and the sky's.
#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "sky/atmosphere/model.h"
#include "sky/atmosphere/probe.h"

namespace skyig::sky {
struct SkyState;
}

namespace skyig::sky {

// One source of light: its JSON key and its radiance along an ENU view direction (unit
// vector), linear Rec.709, cd/m^2 per channel.
struct ProbeComponent {
  std::string key;
  std::function<glm::dvec3(const glm::dvec3& viewEnu)> radiance;
};

// The light sources skyig models for `state` (which must have an ephemeris: a time and place)
// besides the day probe's sky, sun and ground; the moonlit sky from `model`. The functions keep
// references to `model` and `state`.
std::vector<ProbeComponent> nightProbeComponents(const atmosphere::AtmosphereModel& model, const SkyState& state);

// {"luminance_cd_m2": Y, "rgb_cd_m2": [r, g, b]}.
nlohmann::json lightJson(const glm::dvec3& rec709);

// atmosphere::probe's output for `request` (its sun replaced by the state's), each view with
// the night components and "total" added; request.altitude_m is the observer's height above
// the model's ground. Throws std::invalid_argument when the state has no ephemeris, or for the
// probe's own bad values.
nlohmann::json nightProbe(const atmosphere::AtmosphereModel& model, const SkyState& state,
                          atmosphere::ProbeRequest request);

}  // namespace skyig::sky
