#pragma once
// Zodiacal light (docs/night-sky-diffuse.md, "Zodiacal light"): Leinert et al. (1998, A&AS 127,
// 1) table 17, the brightness at 500 nm against helio-ecliptic longitude and latitude, in S10,
// interpolated bilinearly on the table's grid (physics/night/zodiacal.glsl), with the colour of
// sunlight (the dust scatters it almost neutrally in the visible: Leinert et al. 1998 give a
// slight reddening, a few per cent per 100 nm, neglected here).
#include <glm/vec3.hpp>

#include <array>

namespace skyig::sky::night {

inline constexpr int kZodiacalRows = 19;     // helio-ecliptic longitude 0, 5, ..., 45, 60, ..., 180 deg
inline constexpr int kZodiacalColumns = 11;  // ecliptic latitude 0, 5, ..., 30, 45, 60, 75, 90 deg

// The table in S10 (row-major, [longitude][latitude]); the cells the table leaves empty, inside
// the solar corona's glare (elongation < 15 deg near the ecliptic), repeat the nearest value
// along the row: the sun is then low enough that twilight hides them anyway.
const std::array<float, kZodiacalRows * kZodiacalColumns>& zodiacalTableS10();

// Bilinear value at helio-ecliptic (|lambda - lambda_sun|, |beta|) in degrees, S10.
double zodiacalS10(double helioLongitudeDeg, double eclipticLatitudeDeg);

// Linear Rec.709 of sunlight with luminance 1 (CIE 1931 2-degree observer over the solar
// spectrum of physics/spectrum/spectral_data.h, 380-780 nm): the zodiacal light's colour.
const glm::dvec3& sunlightRec709();

// Radiance above the atmosphere (linear Rec.709, cd/m^2 per channel) along a view, both
// vectors J2000 equatorial unit vectors.
glm::dvec3 zodiacalRadiance(const glm::dvec3& viewJ2000, const glm::dvec3& sunJ2000);

}  // namespace skyig::sky::night
