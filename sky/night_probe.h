#pragma once
// `skyig probe` at night (docs/night-sky.md): for a time and place, every view reports each light
// source separately and their sum, each as luminance and linear Rec.709 (scaled so that Y is
// cd/m^2), under these names:
//   sunlit_sky      the physical atmosphere's sky lit by the sun (the day probe's "sky")
//   moonlit_sky     the same sky lit by the moon (Jensen et al. 2001)
//   moon            the moon's disc after extinction; present when the moon is known
//   stars_planets   the mean luminance of the stars and planets within 0.5 degrees of the view
//                   (physics/stars/star_luminance.h), after extinction
//   milky_way       the Milky Way and the unresolved stars, after extinction
//   zodiacal_light  after extinction
//   airglow         after extinction
// and the total: all of them, plus the day probe's sun disc and ground where the view has them.
// With irradiance, the moon's disc (after extinction) and the moonlit sky on a horizontal
// surface, beside the sun's and the sky's. Plain values: commands/probe_json.h prints
// them as JSON, the names as its keys.
// Every light also carries its class A and class B NVIS radiance (sky/nvis, docs/nvis.md),
// weighted through the same spectral extinction as its luminance, and the irradiance adds the
// moonless sky (airglow, zodiacal light, starlight) on the ground.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "ephemeris/time.h"
#include "physics/atmosphere/model.h"
#include "physics/atmosphere/probe.h"
#include "physics/goggle/nvis_sky.h"

namespace skyig::sky {
struct SkyState;
}

namespace skyig::sky {

// One source of light: its name and its radiance along an ENU view direction (unit vector),
// linear Rec.709, cd/m^2 per channel; and its NVIS radiance there (W m^-2 sr^-1), the same
// light weighted by the goggles' response.
struct ProbeComponent {
  std::string name;
  std::function<glm::dvec3(const glm::dvec3& viewEnu)> radiance;
  std::function<nvis::NvisRadiance(const glm::dvec3& viewEnu)> nvis;
};

// The light sources skyig models for `state` (which must have an ephemeris: a time and place)
// besides the day probe's sky, sun and ground; the moonlit sky from `model`. The functions keep
// references to `model` and `state`.
std::vector<ProbeComponent> nightProbeComponents(const atmosphere::AtmosphereModel& model, const SkyState& state);

// A linear Rec.709 light with its luminance (Rec.709 weights).
atmosphere::ProbeLight rec709Light(const glm::dvec3& rec709);

struct NamedProbeLight {
  std::string name;
  atmosphere::ProbeLight light;
  nvis::NvisRadiance nvis{};
};

struct NightProbeView {
  // "sunlit_sky" (the day view's sky), then nightProbeComponents' in their order.
  std::vector<NamedProbeLight> lights;
  // The lights plus the day view's sun disc and ground.
  atmosphere::ProbeLight total;
  nvis::NvisRadiance totalNvis{};
};

// On a horizontal surface at the observer, lux, and NVIS irradiance, W m^-2.
struct NightProbeIrradiance {
  double moonLux = 0.0;         // the disc, after extinction
  double moonlitSkyLux = 0.0;   // the sky the moon lights
  nvis::NvisRadiance moonNvis{};
  nvis::NvisRadiance moonlitSkyNvis{};
  nvis::NvisLight moonlessSky{};  // airglow, zodiacal light, starlight (nvis::moonlessSkyIrradiance)
};

struct NightProbeResult {
  atmosphere::ProbeResult day;                     // for the state's sun
  std::vector<NightProbeView> views;               // one per day.views, in the same order
  std::optional<NightProbeIrradiance> irradiance;  // when day.irradiance is there
  ephemeris::UtcTime utc;
  double latitudeDeg = 0.0;
  double longitudeDeg = 0.0;
};

// The night's lights along one ENU view (unit vector) for `state`, each with its luminance beside
// its NVIS radiance: nightProbeComponents' in their order (not the sunlit sky, the sun or the
// ground, which come from the day probe).
std::vector<NamedProbeLight> nightProbeLights(const atmosphere::AtmosphereModel& model, const SkyState& state,
                                              const glm::dvec3& viewEnu);
// The same from components already made (nightProbeComponents), for many views.
std::vector<NamedProbeLight> nightProbeLights(const std::vector<ProbeComponent>& components, const glm::dvec3& viewEnu);

// atmosphere::probe's result for `request` (its sun replaced by the state's), each view with
// the night's lights and their total; request.altitudeM is the observer's height above the
// model's ground. Throws std::invalid_argument when the state has no ephemeris, or for the
// probe's own bad values.
NightProbeResult nightProbe(const atmosphere::AtmosphereModel& model, const SkyState& state,
                            atmosphere::ProbeRequest request);

}  // namespace skyig::sky
