#pragma once
// A subtle, deterministic twinkle: a star's intensity factor as a function of its catalogue
// number, the simulation time and the airmass, so a replay twinkles identically.
//
// The amplitude follows Young's (1967, AJ 72, 747) airmass law of scintillation, sigma_I
// proportional to X^1.75, confirmed by Dravins et al. (1998, PASP 110, 610, "Atmospheric
// intensity scintillation of stars III"). Its zenith value is set low on purpose (2%: a
// naked-eye star hardly twinkles overhead) and capped at 25% near the horizon, where the eye
// sees the strongest twinkling. The time signal is two sines of 0.7-3 Hz with per-star
// frequencies and phases: zero mean, so a star's illuminance averages to its true value.
namespace skyig::sky::night {

inline constexpr double kScintillationZenith = 0.02;
inline constexpr double kScintillationMax = 0.25;

// Relative amplitude at airmass X (>= 1).
double scintillationAmplitude(double airmass);

// Intensity factor, in [1 - amplitude, 1 + amplitude].
double scintillationFactor(int starId, double timeS, double airmass);

// Plane-parallel-free airmass of Kasten & Young (1989, Applied Optics 28, 4735), finite at the
// horizon (about 38), from the apparent altitude in radians (clamped at 0).
double airmassKastenYoung(double altitudeRad);

}  // namespace skyig::sky::night
