#pragma once
// The relative spectral response of night-vision goggles (NVIS: night vision imaging systems),
// G_A(lambda) for class A and G_B(lambda) for class B, the weights of the NVIS radiance
// (docs/nvis.md).
//
// MIL-STD-3009 (2 February 2001, superseding MIL-L-85762A of 1988) defines the NVIS radiance of
// a source of spectral radiance N(lambda) as NR = G_max * integral over 450-930 nm of
// G(lambda) N(lambda) dlambda, with G the relative response of the class's goggle (peak 1) and
// G_max its absolute peak. A class A goggle has a 625 nm "minus-blue" objective filter, a
// class B goggle a 665 nm one (MIL-L-85762A, 1.3; of both standards only the first pages could
// be read for this work, docs/nvis.md). skyig reports the integral alone,
// integral of G(lambda) L(lambda) dlambda in SI units (W m^-2 sr^-1 for a radiance, W m^-2 for
// an irradiance): the "NVIS-weighted radiance" without the standard's G_max and cm^-2.
//
// PROVISIONAL: the standard tabulates G_A and G_B in 10 nm steps from 450 to 930 nm; that
// table could not be found for this work, so the response below is a stand-in, NOT the
// standard's numbers: each class's filter as a logistic edge of 5 nm scale with its 50% point at
// the filter's wavelength (625 or 665 nm), over a flat photocathode response to the band's end
// at 930 nm. A real Gen III photocathode falls off beyond about 850 nm, so the stand-in
// over-weights the far end of the band. Replace kNvisResponseTable's rows by the standard's
// table when it is at hand; every NVIS figure in skyig follows from them.
#include <array>

namespace skyig::sky::nvis {

enum class NvisClass { A, B };

inline constexpr double kNvisMinNm = 450.0;   // the standard's integration limits
inline constexpr double kNvisMaxNm = 930.0;
inline constexpr double kNvisTableStepNm = 10.0;
inline constexpr int kNvisTableSize = 49;     // 450, 460, ..., 930 nm
inline constexpr bool kNvisResponseProvisional = true;

// The response at the table's wavelengths (class A, class B).
const std::array<double, kNvisTableSize>& nvisResponseTable(NvisClass nvisClass);

// G(lambda), interpolated linearly in the table; 0 outside [450, 930] nm.
double nvisResponse(NvisClass nvisClass, double wavelengthNm);

}  // namespace skyig::sky::nvis
