#pragma once
// The diffuse night light on the CPU: the Milky Way with the unresolved stars,
// the zodiacal light and the airglow, each after extinction by the state's atmosphere
// (sky::SkyState::extinction), from the same physics as the GL pass (render/passes/night/night_diffuse_pass.h,
// render/passes/night/night_diffuse.frag). docs/night-sky-diffuse.md gives the models.
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <optional>

#include "ephemeris/ephemeris.h"
#include "physics/atmosphere/extinction_profile.h"
#include "physics/night/milky_way_map.h"

namespace skyig::sky::night {

// Airglow's zenith brightness in V: 145 S10, i.e. 22.4 mag/arcsec^2 (Roach & Gordon 1973, as
// tabulated for a dark mid-latitude site at average solar activity: airglow 145 S10, zodiacal
// light 60 S10, scattered starlight ~15 S10, total ~220 S10 = 21.9 mag/arcsec^2 at the zenith).
// It varies by a factor of about 2 with the solar cycle (Leinert et al. 1998); not modelled.
inline constexpr double kAirglowZenithS10 = 145.0;

// Linear Rec.709 of the airglow with luminance 1. Its V-band light is the OI 557.7 nm green
// line, the Na D lines (589.3 nm) and a pseudo-continuum (NO2, O2) across the band (Roach &
// Gordon 1973; the ESO sky model of Noll et al. 2012 shows the same parts). The shares of V
// below are an estimate from those spectra, not a fit: the line about a third, sodium a tenth,
// the continuum (taken as equal-energy) the rest; the result is a pale yellowish green.
inline constexpr double kAirglowGreenLineShare = 0.35;
inline constexpr double kAirglowSodiumShare = 0.10;
const glm::dvec3& airglowRec709();

struct NightDiffuseSky {
  glm::dmat3 enuToJ2000{1.0};             // view ENU -> J2000 equatorial (column-major GLM)
  glm::dvec3 sunJ2000{1.0, 0.0, 0.0};      // unit vector
  glm::dvec3 airglowZenith{0.0};           // linear Rec.709 cd/m^2 above the lower atmosphere
  std::shared_ptr<const atmosphere::ExtinctionProfile> extinction;  // null: no atmosphere
  std::shared_ptr<const MilkyWayMap> milkyWay;
};

// From an ephemeris (J2000 frame, the sun) and the extinction at the observer (null: none).
// Loads the Milky Way map on first use (MilkyWayMap::standard()) unless `withMilkyWay` is false.
NightDiffuseSky makeNightDiffuseSky(const ephemeris::SkyEphemeris& sky,
                                    std::shared_ptr<const atmosphere::ExtinctionProfile> extinction,
                                    bool withMilkyWay = true);

// Linear Rec.709 radiance, cd/m^2 per channel, at the observer.
struct NightDiffuseRadiance {
  glm::dvec3 milkyWay{0.0};
  glm::dvec3 zodiacal{0.0};
  glm::dvec3 airglow{0.0};
  glm::dvec3 total() const { return milkyWay + zodiacal + airglow; }
};

// Along a view (ENU, normalised here). Throws std::invalid_argument for a zero or non-finite
// view.
NightDiffuseRadiance nightDiffuseRadiance(const NightDiffuseSky& sky, const glm::dvec3& viewEnu);

// The diffuse night light along a view without the Milky Way map (`sky` made with
// withMilkyWay = false): airglow and zodiacal light, and for the Milky Way and the unresolved
// stars their calibrated floor of kPoleS10 everywhere, dimmed by the extinction (the band adds
// ~10% more). What the eye's view sphere and the ground's light use: the worker builds a state
// per host update and never loads the map for it.
glm::dvec3 nightDiffuseRadianceWithoutMap(const NightDiffuseSky& sky, const glm::dvec3& viewEnu);

// The diffuse night light's illuminance on a horizontal surface at the observer (linear Rec.709
// lux per channel, luminance-weighted sum = lux): E = integral of L cos(theta) dOmega over the
// upper hemisphere, of nightDiffuseRadianceWithoutMap over 8 x 16 directions (~0.1 ms). With the resolved stars (physics/stars/star_field.h horizontalIlluminance) it
// is what lights the terrain on a moonless night: ~1e-3 lux at a dark site, airglow about half
// of it (Roach & Gordon 1973; the "starlight" illuminance of 1-2e-3 lux often quoted includes
// airglow and zodiacal light).
glm::dvec3 nightDiffuseIlluminance(const ephemeris::SkyEphemeris& sky,
                                   std::shared_ptr<const atmosphere::ExtinctionProfile> extinction);

// The extinction factor (linear Rec.709) of a view, as the GL pass samples it.
glm::dvec3 nightExtinction(const NightDiffuseSky& sky, const glm::dvec3& viewEnu);

}  // namespace skyig::sky::night
