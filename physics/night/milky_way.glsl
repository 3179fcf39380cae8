#ifndef SKYIG_NIGHT_MILKY_WAY_GLSL
#define SKYIG_NIGHT_MILKY_WAY_GLSL
// Where a direction falls on the Milky Way panorama (Mellinger's all-sky map, equirectangular in
// J2000 equatorial coordinates: RA = 90 deg - 360 deg (x + 0.5) / width, Dec = 90 deg - 180 deg
// (y + 0.5) / height, row 0 at the top; physics/night/data/README.md), and the galactic frame the map
// is calibrated in (physics/night/milky_way_map.h).

// Texture coordinate (u, v) of a J2000 unit vector: u = fract(1/4 - RA / 2 pi), v = (90 deg -
// Dec) / 180 deg, v = 0 at the map's top row (the rows are uploaded top first).
vec2 milkyWayTexCoord(IN(vec3) j2000) {
  Float ra = atan(j2000.y, j2000.x);
  Float dec = asin(clamp(j2000.z, -1.0, 1.0));
  Float u = 0.25 - ra / (2.0 * 3.14159265358979);
  u = u - floor(u);
  return vec2(u, 0.5 - dec / 3.14159265358979);
}

// The J2000 unit vector at the centre of a texture coordinate: the inverse of the above.
vec3 milkyWayDirection(IN(vec2) uv) {
  Float ra = (0.25 - uv.x) * 2.0 * 3.14159265358979;
  Float dec = (0.5 - uv.y) * 3.14159265358979;
  return vec3(cos(dec) * cos(ra), cos(dec) * sin(ra), sin(dec));
}

// Galactic latitude (radians) of a J2000 unit vector: the third row of the ICRS-to-galactic
// rotation (Hipparcos catalogue, vol. 1, section 1.5.3: north galactic pole at RA 192.85948 deg,
// Dec 27.12825 deg).
Float galacticSinLatitude(IN(vec3) j2000) {
  return clamp(dot(vec3(-0.8676661490, -0.1980763734, 0.4559837762), j2000), -1.0, 1.0);
}

Float galacticLatitude(IN(vec3) j2000) { return asin(galacticSinLatitude(j2000)); }

#endif
