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

// The moon's V magnitude at phase angle phi, at its mean distance and the sun's: Krisciunas &
// Schaefer (1991, PASP 103, 1033, eq. 20), m(phi) = -12.73 + 0.026 |phi| + 4e-9 phi^4 (phi in
// degrees), their fit to the measured lunar photometry. The first quarter is 2.6 magnitudes
// (0.091) below the full moon, where eq. 9's smooth Lommel-Seeliger sphere keeps 0.377: the
// real surface's roughness and its opposition surge make a quarter moon a tenth, not a third,
// of the full. The fit holds to phi of about 150 deg; the law goes on falling beyond.
inline constexpr double kMeanMoonDistanceKm = 384400.0;
double lunarMagnitude(double phaseAngleRad);
// lunarMagnitude as a brightness relative to the full moon's, 1 at phi = 0.
double lunarPhaseFunction(double phaseAngleRad);

// What turns eq. 9's sunlit moon into the measured one: the irradiance of lunarMagnitude
// (eq. 11) over eq. 9's sunlit irradiance with C_a, both at the mean distances. 2.33 at full
// moon (eq. 9 with C_a = 0.072 gives 1.33e-3 W/m^2, the magnitude -12.73 gives 3.10e-3 W/m^2,
// 0.29 lux), 0.56 at first quarter; 0 where eq. 9's phase law is. The disc keeps Lommel-
// Seeliger's distribution over its surface (physics/moon/moon.glsl), scaled by this factor of
// the phase alone, as Hapke's opposition term would.
double lunarOppositionFactor(double phaseAngleRad);

// Eq. 9 with the measured sunlit moon: irradiance (W/m^2) at the observer from a moon at phase
// angle phi and distance d (km), E = 2/3 C_a r_m^2 / d^2 (E_sm F(phi) O(phi) + E_em), with
// O = lunarOppositionFactor. The sunlight at the moon E_sm follows from the sun-moon distance;
// the earthshine E_em from eq. 9's law with the earth's albedo at the earth's phase seen from
// the moon (pi - phi), lit from the observer's direction (its own phase 0).
double moonIrradiance(double phaseAngleRad, double moonDistanceKm, double sunMoonDistanceKm);

// Eq. 11 (corrected): irradiance of a point source of visual magnitude m, 10^(-(m + 19) / 2.5) W/m^2.
double irradianceFromMagnitude(double magnitude);

// Eq. 10, its inverse: m = -(19 + 2.5 log10(E)).
double magnitudeFromIrradiance(double irradianceWm2);

// Eq. 12: effective colour temperature (K) from the colour index B-V, 7000 K / (B-V + 0.56).
// Throws std::invalid_argument for B-V <= -0.4 (hotter than any catalogued star) or NaN.
double colourTemperatureFromBv(double bMinusV);

}  // namespace skyig::ephemeris
