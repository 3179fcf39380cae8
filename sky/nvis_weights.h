#pragma once
// What turns a goggle channel's passes from the eye's band into the goggles': for each light the
// sky passes draw, its NVIS radiance per cd/m^2 of its luminance, from the same spectra and
// transmittance the probe uses (sky/night_probe.h, physics/goggle/), so a goggle channel's image and
// `skyig probe`'s NVIS figures are one model. The passes keep computing each light's linear
// Rec.709 radiance and, in a goggle's band, write its luminance times its weight into all three
// channels (render/glsl/band.glsl): the sky's colour already carries everything the passes
// know of the light's path; the weight adds what the eye's band cannot see, the light beyond
// 700 nm.
//
// Each weight is one number per frame and channel, taken along the channel's centre where a
// light's colour depends on its path (the diffuse night lights through the state's spectral
// extinction; the moon and the sun along their own directions). Across a 40 deg goggle the
// transmittance's colour changes little above 10 deg elevation; towards the horizon the
// weight of the centre is kept (docs/nvis.md gives the error).
#include "sky/channel.h"
#include "physics/goggle/night_spectra.h"
#include "physics/goggle/nvis_response.h"
#include "sky/sky_state.h"

#include <glm/vec3.hpp>

namespace skyig::sky {

struct NvisWeights {
  bool nvis = false;       // false: the eye's band, every weight 1 (the passes leave their colour)
  double sunlitSky = 1.0;  // W m^-2 sr^-1 per cd/m^2: the sky and the ground in sunlight
  double sunDisc = 1.0;    // the sun's disc, through the air along it
  double moonlitSky = 1.0; // the sky and the ground in moonlight
  double moon = 1.0;       // the moon's disc, through the air along it
  double airglow = 1.0;
  double zodiacal = 1.0;
  double milkyWay = 1.0;     // the Milky Way and the unresolved stars
  double nightGround = 1.0;  // the terrain under the night's own light (the airglow's colour: most of it)
};

// The weights of `band` for `state` seen along the ENU direction `viewEnu` (the channel's centre).
NvisWeights nvisWeights(SpectralBand band, const SkyState& state, const glm::dvec3& viewEnu);

// The haze's extinction in the goggle's band over its extinction at 550 nm: aerosols scatter
// less at longer wavelengths, extinction ~ lambda^-alpha (Angstrom 1929, "On the atmospheric
// transmission of sun radiation and on dust in the air", Geografiska Annaler 11, 156-166), with
// alpha = 1.3, the value Angstrom found for continental air; taken at the class's mean
// wavelength, the integral of lambda G(lambda) over that of G (physics/goggle/nvis_response.h).
double nvisHazeExtinctionScale(nvis::NvisClass nvisClass);

// The layers a goggle channel draws: the haze below the tables' visibility thinner by
// nvisHazeExtinctionScale (a goggle sees farther through haze than the eye), the fog, rain, snow,
// dust and cloud as the eye's (droplets, drops and grains far larger than the wavelength: grey),
// and their light in the goggle's band: each layer's top lit by `state`'s sun and moon with each
// light's top irradiance times the NVIS radiance per cd/m^2 of what lights it (the direct light's
// and its sky's, in their shares of the top's lux: grey droplets keep that spectrum). A goggle's
// table (FogTables' nvisA, nvisB) therefore holds NVIS radiance as the Rec.709 luminance of its
// rgb, which the sky pass adds to the air's NVIS radiance: a fog reads brighter in a goggle than
// the blue sky of the same luminance, as sunlight does, and a moonlit deck as moonlight.
weather::FogLayers goggleFogLayers(const SkyState& state, nvis::NvisClass nvisClass);

// The state's precomputed table (FogTables) for a channel of `band`: the eye's, or its goggle
// class's; null where the state has none.
std::shared_ptr<const std::vector<glm::vec4>> fogTableFor(const FogState& fog, SpectralBand band);
// The same without the broken cloud decks (FogTables' clear*; null without one).
std::shared_ptr<const std::vector<glm::vec4>> clearFogTableFor(const FogState& fog, SpectralBand band);

// The NVIS irradiance per lux of a blackbody of `temperatureK` above the atmosphere (the stars'
// weight: each star's own, from the temperature it keeps), interpolated in a table of
// log-spaced temperatures from 1500 K to 50000 K (clamped beyond) that is within 0.1% of the
// integral (tests/physics/goggle).
double nvisPerLuxOfBlackbody(double temperatureK, nvis::NvisClass nvisClass);

// The class of a goggle's band (band must not be Visible).
nvis::NvisClass nvisClassOf(SpectralBand band);

}  // namespace skyig::sky
