#ifndef SKYIG_NIGHT_ZODIACAL_GLSL
#define SKYIG_NIGHT_ZODIACAL_GLSL
// Zodiacal light: sunlight scattered by interplanetary dust, tabulated by Leinert et al. (1998,
// A&AS 127, 1, table 17) against helio-ecliptic longitude (lambda - lambda_sun, 0..180 deg,
// symmetric about the sun) and ecliptic latitude (|beta|, 0..90 deg), on a grid that is 5 deg
// wide near the sun and 15 deg wide far from it. The table's values live in a texture (GPU) and
// an array (CPU, physics/night/zodiacal_light.h); this file holds the geometry both share.

const Float kZodiacalLongitudeSamples = 19.0;  // 0, 5, ..., 45, 60, ..., 180 deg
const Float kZodiacalLatitudeSamples = 11.0;   // 0, 5, ..., 30, 45, 60, 75, 90 deg
// Mean obliquity of the ecliptic at J2000 (IAU 2006: 84381.406"): the table is heliocentric-
// ecliptic; the ecliptic's slow precession (47" a century) is below its resolution.
const Float kObliquityJ2000Rad = 23.439279444 * 3.14159265358979 / 180.0;

// J2000 equatorial -> J2000 ecliptic (a rotation by the obliquity about the equinox).
vec3 equatorialToEcliptic(IN(vec3) v) {
  Float c = cos(kObliquityJ2000Rad);
  Float s = sin(kObliquityJ2000Rad);
  return vec3(v.x, c * v.y + s * v.z, -s * v.y + c * v.z);
}

// (|lambda - lambda_sun|, |beta|) in degrees of a view, both J2000 equatorial unit vectors.
vec2 helioEclipticCoordinates(IN(vec3) viewJ2000, IN(vec3) sunJ2000) {
  vec3 v = equatorialToEcliptic(viewJ2000);
  vec3 s = equatorialToEcliptic(sunJ2000);
  Float lon = atan(v.y, v.x) - atan(s.y, s.x);
  Float degree = 180.0 / 3.14159265358979;
  lon = abs(lon * degree);
  lon = lon - 360.0 * floor(lon / 360.0);
  lon = min(lon, 360.0 - lon);
  Float lat = abs(asin(clamp(v.z, -1.0, 1.0))) * degree;
  return vec2(lon, lat);
}

// Fractional (row, column) index into table 17 of helio-ecliptic (longitude, latitude) degrees.
vec2 zodiacalTableIndex(IN(vec2) lonLatDeg) {
  Float lon = clamp(lonLatDeg.x, 0.0, 180.0);
  Float lat = clamp(lonLatDeg.y, 0.0, 90.0);
  Float row = lon < 45.0 ? lon / 5.0 : 9.0 + (lon - 45.0) / 15.0;
  Float column = lat < 30.0 ? lat / 5.0 : 6.0 + (lat - 30.0) / 15.0;
  return vec2(row, column);
}

// Texture coordinate of that index in a texture of kZodiacalLatitudeSamples columns (s, by
// latitude) and kZodiacalLongitudeSamples rows (t, by longitude), texel centres on the grid.
vec2 zodiacalTexCoord(IN(vec2) lonLatDeg) {
  vec2 index = zodiacalTableIndex(lonLatDeg);
  return vec2((index.y + 0.5) / kZodiacalLatitudeSamples, (index.x + 0.5) / kZodiacalLongitudeSamples);
}

#endif
