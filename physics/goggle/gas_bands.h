#pragma once
// The molecular absorption bands in the goggles' band that skyig's precomputed atmosphere does
// not have (its medium is Rayleigh, aerosol and ozone, to 830 nm): the oxygen B (687 nm) and
// A (762 nm) bands and the water vapour bands near 720, 820 and 900-930 nm, as vertical optical
// depths per 5 nm bin of the NVIS grid (night_spectra.h), taken from a published spectrum:
//
// ASTM G-173-03's direct normal spectrum (SMARTS 2.9.2: US Standard Atmosphere, 1.42 cm of
// precipitable water, rural aerosol of optical depth 0.084 at 500 nm, at an air mass of 1.5)
// over its extraterrestrial spectrum, both at 1 nm (the file pvlib distributes,
// pvlib/data/ASTMG173.csv), summed over the 5 nm around each grid wavelength, gives the bin's
// optical depth per air mass, -ln(direct / extraterrestrial) / 1.5. Through the band-free
// bins 680, 745, 750, 780, 785, 860, 870, 875 and 880 nm that depth is a power law, 0.0632 at
// 830 nm falling as lambda^-2.71 (Rayleigh, aerosol and ozone; within 3% at every one of
// them); the bands are what lies above it. Bins not listed absorb nothing here.
//
// Along a view, each gas's depth is scaled by the air mass (Kasten & Young 1989) and by the
// fraction of the gas above the observer: oxygen with the air's scale height (8 km), water
// vapour with its own (2 km, the usual exponential profile of precipitable water). Linear in
// the air mass: the weak-line limit. The bands' strongest lines saturate, so towards the
// horizon (air mass 10 and more) this overstates their absorption; at 5 nm resolution the bins
// also average over lines a real spectrum resolves.
#include <array>

namespace skyig::sky::nvis {

struct GasBand {
  double wavelengthNm;   // the grid bin's centre
  double oxygenDepth;    // vertical optical depth at sea level
  double waterDepth;
};
inline constexpr std::array<GasBand, 27> kGasBands{{
    {685.0, 0.0432, 0.0}, {690.0, 0.1027, 0.0}, {695.0, 0.0451, 0.0},  // O2 B band
    {700.0, 0.0, 0.0296}, {715.0, 0.0, 0.0312}, {720.0, 0.0, 0.1311}, {725.0, 0.0, 0.1180},
    {730.0, 0.0, 0.1001}, {735.0, 0.0, 0.0307},                      // H2O 0.72 um
    {760.0, 0.3594, 0.0}, {765.0, 0.3731, 0.0}, {770.0, 0.0173, 0.0},  // O2 A band
    {810.0, 0.0, 0.0203}, {815.0, 0.0, 0.1267}, {820.0, 0.0, 0.0973}, {825.0, 0.0, 0.1048},
    {830.0, 0.0, 0.0947}, {835.0, 0.0, 0.0363},                      // H2O 0.82 um
    {890.0, 0.0, 0.0068}, {895.0, 0.0, 0.0971}, {900.0, 0.0, 0.2088}, {905.0, 0.0, 0.1259},
    {910.0, 0.0, 0.1889}, {915.0, 0.0, 0.2092}, {920.0, 0.0, 0.1377}, {925.0, 0.0, 0.1031},
    {930.0, 0.0, 0.4233},                                            // H2O 0.94 um, its blue wing
}};
inline constexpr double kOxygenScaleHeightM = 8000.0;
inline constexpr double kWaterScaleHeightM = 2000.0;

// Kasten & Young (1989): the relative optical air mass at an apparent elevation (degrees),
// 1 at the zenith, 38 at the horizon.
double relativeAirMass(double elevationDeg);

// The transmittance of the gases in the bin of `wavelengthNm` (a grid wavelength; 1 between
// bands) along a view at `elevationRad` from `altitudeM`; 0 below the horizon is the caller's.
double gasTransmittance(double wavelengthNm, double elevationRad, double altitudeM);

}  // namespace skyig::sky::nvis
