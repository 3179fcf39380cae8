#pragma once
// Night-sky irradiances of Wang, Ji & Zhang 2011, "Realistic sky rendering in real time",
// eq. 9-12, after Jensen, Durand, Stark, Premoze, Dorsey & Shirley 2001, "A physically-based
// night sky model", with two misprints of the former corrected: eq. 9's last factor is
// 1 - sin(phi/2) tan(phi/2) ln(cot(phi/4)) (printed with cos), and eq. 11 is
// E = 10^(-(m + 19) / 2.5) (printed 10^(-m - 19)), the inverse of eq. 10.

namespace skyig::ephemeris {

inline constexpr double kMoonRadiusKm = 1737.4;
inline constexpr double kSunRadiusKm = 695700.0;    // IAU 2015 nominal
inline constexpr double kEarthRadiusKm = 6371.0;    // mean
inline constexpr double kSolarConstantWm2 = 1361.0; // total solar irradiance at 1 au (Kopp & Lean 2011)
inline constexpr double kMoonAlbedo = 0.072;        // C_a, eq. 9
inline constexpr double kEarthAlbedo = 0.30;        // Bond albedo, for earthshine on the moon

// Lunar phase law of eq. 9: 1 - sin(phi/2) tan(phi/2) ln(cot(phi/4)); 1 at full (phi = 0) and
// 0 at new moon (phi = pi). phi in radians, clamped to [0, pi].
double lunarPhaseLaw(double phaseAngleRad);

// Eq. 9: irradiance (W/m^2) at the observer from a moon at phase angle phi and distance d (km),
// E = 2/3 C_a r_m^2 / d^2 (E_sm + E_em) F(phi). The sunlight at the moon E_sm follows from the
// sun-moon distance; the earthshine E_em from the same law with the earth's albedo at the earth's
// phase seen from the moon (pi - phi).
double moonIrradiance(double phaseAngleRad, double moonDistanceKm, double sunMoonDistanceKm);

// Eq. 11 (corrected): irradiance of a point source of visual magnitude m, 10^(-(m + 19) / 2.5) W/m^2.
double irradianceFromMagnitude(double magnitude);

// Eq. 10, its inverse: m = -(19 + 2.5 log10(E)).
double magnitudeFromIrradiance(double irradianceWm2);

// Eq. 12: effective colour temperature (K) from the colour index B-V, 7000 K / (B-V + 0.56).
// Throws std::invalid_argument for B-V <= -0.4 (hotter than any catalogued star) or NaN.
double colourTemperatureFromBv(double bMinusV);

}  // namespace skyig::ephemeris
