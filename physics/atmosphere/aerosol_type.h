#pragma once
// Named aerosol types: the ten of OPAC (Hess, Koepke and Schult 1998, "Optical Properties of
// Aerosols and Clouds: The Software Package OPAC", BAMS 79, 831-844, Table 4), each with its
// extinction spectrum, single-scattering albedo, Mie phase function and growth with humidity,
// at OPAC's eight humidity classes. The numbers are OPAC's components mixed as OPAC mixes them
// (aerosol_type_opac.inc, written by derive_aerosol_types.py from OPAC's files). The type sets
// what the aerosol is; the visibility sets how much of it there is (conditions.h).
#include <array>
#include <optional>
#include <string_view>

namespace skyig::atmosphere {

struct Medium;

enum class AerosolType {
  bruneton2017,  // not OPAC: Bruneton's 2017 demo aerosol, grey, Cornette-Shanks g (the medium's)
  continentalClean,
  continentalAverage,
  continentalPolluted,
  urban,
  desert,
  maritimeClean,
  maritimePolluted,
  maritimeTropical,
  arctic,
  antarctic,
};

// "continental_clean" and so on, as the configuration writes them; "bruneton2017".
std::string_view aerosolTypeName(AerosolType type);
std::optional<AerosolType> parseAerosolType(std::string_view name);
// All names, comma-separated, for error messages.
std::string_view aerosolTypeNames();

// Samples of the tabulated phase function: theta_i = pi (i / (N - 1))^2, dense at the forward
// peak (ATMOSPHERE_MIE_PHASE_SAMPLES in parameters.glsl).
inline constexpr int kMiePhaseSamples = 64;

struct AerosolOptics {
  double extinctionAt550PerKm;  // of OPAC's standard mixture of the type (its growth with humidity)
  double singleScatteringAlbedo;
  double angstromExponent;  // of the extinction, 400-700 nm
  double asymmetry;         // <cos theta> of the phase function
  double scaleHeightM;      // a uniform layer of the ground's density with the type's optical depth
  std::array<double, kMiePhaseSamples> logPhase;  // ln p(theta_i), p in sr^-1, integrating to 1
};

// The integral over the sphere of the phase function the shader interpolates from a table.
double tabulatedPhaseIntegral(const std::array<double, kMiePhaseSamples>& logPhase);

// OPAC's relative humidity classes, and the one nearest a humidity in [0, 1]: each medium is a
// table build, so the host's humidity picks one of the eight OPAC computed.
inline constexpr std::array<double, 8> kOpacHumidityClasses{0.0, 0.5, 0.7, 0.8, 0.9, 0.95, 0.98, 0.99};
double nearestHumidityClass(double relativeHumidity);

// The type's optics at a relative humidity in [0, 0.99], interpolated between OPAC's classes
// (linear in humidity; the phase function and the extinction in their logarithms). Throws
// std::invalid_argument for bruneton2017 or a humidity outside [0, 0.99].
AerosolOptics aerosolOptics(AerosolType type, double relativeHumidity);

// The medium's aerosol made of the type at the humidity: its albedo, Angstrom exponent, scale
// height and phase function; its amount (the extinction at 550 nm) kept. bruneton2017 only
// names the type: the medium's own albedo, exponent, scale height and Cornette-Shanks g stay.
Medium withAerosolType(const Medium& base, AerosolType type, double relativeHumidity);

// The same with OPAC's standard amount of the type at the humidity (its extinction at 550 nm):
// what a configuration naming a type gets until a visibility says how much.
Medium withStandardAerosol(const Medium& base, AerosolType type, double relativeHumidity);

}  // namespace skyig::atmosphere
