#pragma once
// Run-time conditions that change the medium: meteorological visibility, relative humidity
// and ground albedo. Applying them yields a new Medium (and so a new parameter hash and a new
// set of tables).
#include <optional>

#include "physics/atmosphere/medium.h"
#include "physics/common/sky_conditions.h"

namespace skyig::atmosphere {

struct Conditions {
  // Meteorological visibility at the ground, km. Unset: the medium's own aerosol density.
  std::optional<double> visibilityKm;
  // Relative humidity in [0, 0.99]; unset: the medium's aerosols as given.
  std::optional<double> relativeHumidity;
  // Lambertian ground albedo in [0, 1]; unset: the medium's.
  std::optional<double> groundAlbedo;
};

// Koschmieder's relation (physics/common/sky_conditions.h), with beta_ext the total extinction at
// 550 nm at the ground.
inline constexpr double kKoschmiederConstant = sky::kKoschmiederConstant;

// The visibilities the configuration, the command line and the host may give (km): from a
// 50 m fog to a host's "unlimited"; past cleanAirVisibilityKm they are all clean air.
inline constexpr double kSmallestVisibilityKm = 0.05;
inline constexpr double kLargestVisibilityKm = 1000.0;

// The visibility of air without aerosols, the molecules alone (about 288 km).
double cleanAirVisibilityKm(const Medium& medium);

// Aerosol extinction at 550 nm at the ground (m^-1) giving the visibility with the medium's
// molecules: zero for a visibility at or beyond clean air's (a host's "unlimited"); throws
// std::invalid_argument if the visibility is not a finite positive number.
double mieExtinctionForVisibility(const Medium& medium, double visibilityKm);

// Visibility (km) of a medium by the same relation.
double visibilityOf(const Medium& medium);

// Hygroscopic growth of the aerosol extinction with relative humidity, relative to the dry
// state the medium describes at kReferenceHumidity (Kasten 1969, Hanel 1976:
// f = ((1 - RH) / (1 - RH_ref))^-gamma, gamma = 0.25 for continental aerosol).
inline constexpr double kReferenceHumidity = 0.5;
inline constexpr double kHanelGamma = 0.25;
double humidityGrowthFactor(double relativeHumidity);

// The medium with another aerosol extinction at 550 nm. More aerosol than the medium's is the
// medium's aerosol grown by water (humidity, mist, fog): water scatters and hardly absorbs in
// the visible, and the dry particles' absorbing matter does not grow (Hanel 1976), so the
// absorption coefficient stays the medium's, beta_abs = beta_M (1 - omega), and the
// single-scattering albedo rises towards 1: 0.9 in the clean medium, 0.995 at 40 km, 0.9999 in
// a 0.5 km fog. Left at 0.9, a fog absorbed a tenth of the light at every scattering and a
// 0.5 km fog's sky was twenty times too dark. Less aerosol than the medium's is fewer particles
// of the same kind (the albedo unchanged). The Angstrom exponent is kept (an approximation:
// fog droplets are grey), so that the optical depth stays linear in beta_M at every wavelength
// and tables blend exactly between visibilities (tables/visibility_blend.h).
// An OPAC aerosol type (aerosol_type.h) keeps its albedo: its water is set by the humidity,
// and at a given humidity more of it is more particles of the same kind.
Medium withAerosolExtinction(const Medium& base, double mieExtinctionPerM);

// The medium under the conditions; visibility, when given, fixes the aerosol extinction
// (it is measured on the humid aerosol, so humidity then changes no amount); otherwise
// humidity scales the medium's aerosol extinction. With an OPAC aerosol type the humidity also
// sets what the particles are (their albedo, spectrum and phase function at OPAC's nearest
// humidity class), and their growth is OPAC's. Throws std::invalid_argument naming a bad value.
Medium applyConditions(const Medium& base, const Conditions& conditions);

}  // namespace skyig::atmosphere
