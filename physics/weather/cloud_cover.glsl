#ifndef SKYIG_WEATHER_CLOUD_COVER_GLSL
#define SKYIG_WEATHER_CLOUD_COVER_GLSL
// Where a broken cloud layer has cloud: a 2D field over the ground (the 2.5D weather map of
// Schneider & Vos 2015, "The real-time volumetric cloudscapes of Horizon Zero Dawn", SIGGRAPH
// course, drawn here as a coverage mask over the layer's slab rather than ray marched), a sum of
// four octaves of value noise on an integer lattice, periodic over kCloudPeriodCells cells so that
// a position kept modulo the period in double on the CPU (physics/weather/cloud_deck.h) holds its
// fraction of a cell in single precision anywhere on the planet. Integer hashing, not sin(), so
// the GPU and the C++ compile of this file draw the same clouds (to float rounding).

const int kCloudPeriodCells = 256;

// One lattice point's value in [0, 1]: a 32-bit integer hash (Wellons' "lowbias32" mix) of the
// point and the layer's seed.
Float cloudLatticeValue(int ix, int iy, int seed) {
  uint h = uint(ix & (kCloudPeriodCells - 1)) * 0x8da6b343u + uint(iy & (kCloudPeriodCells - 1)) * 0xd8163841u +
           uint(seed) * 0xcb1ab31fu;
  h ^= h >> 16u;
  h *= 0x7feb352du;
  h ^= h >> 15u;
  h *= 0x846ca68bu;
  h ^= h >> 16u;
  return Float(h >> 8u) * (1.0 / 16777215.0);
}

// Value noise at p (cells), smoothed by the quintic fade (Perlin 2002): C2 across cell edges, so
// a cloud's edge has no crease.
Float cloudValueNoise(vec2 p, int seed) {
  vec2 i = floor(p);
  vec2 f = p - i;
  vec2 w = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
  int x = int(i.x);
  int y = int(i.y);
  Float a = cloudLatticeValue(x, y, seed);
  Float b = cloudLatticeValue(x + 1, y, seed);
  Float c = cloudLatticeValue(x, y + 1, seed);
  Float d = cloudLatticeValue(x + 1, y + 1, seed);
  return mix(mix(a, b, w.x), mix(c, d, w.x), w.y);
}

// Four octaves, each twice the frequency and half the amplitude of the one before (in [0, 1]).
// The octaves' periods divide the first's, so the sum keeps kCloudPeriodCells.
Float cloudField(vec2 p, int seed) {
  Float sum = 0.0;
  Float amplitude = 0.5;
  for (int k = 0; k < 4; ++k) {
    sum += amplitude * cloudValueNoise(p, seed + 17 * k);
    p *= 2.0;
    amplitude *= 0.5;
  }
  return sum / 0.9375;
}

// The share of cloud at p in [0, 1]: where the field passes the layer's threshold, with an edge
// `softness` wide in the field's units. The CPU sets the threshold from the coverage
// (cloud_deck.h: cloudThreshold), so the sky's share where this is above 1 - 1/e (an optical
// depth over 1 at the layer's full depth) is the coverage.
Float cloudMask(vec2 p, int seed, Float threshold, Float softness) {
  return smoothstep(threshold - softness, threshold + softness, cloudField(p, seed));
}

// How far a view's crossing `d` metres off has gone from the field to its mean: none nearer than
// `start`, all of it beyond 4 start (start: cloud_deck.h, kCloudFadeCells cells).
Float cloudFadeWeight(Float d, Float start) { return smoothstep(start, 4.0 * start, d); }

// Distance along a view of cosine mu from an eye h metres above a sphere of radius R to the
// sphere at height h_s, on the view's way (the far root above the eye, the near one below); -1
// where the view never reaches it.
Float distanceToHeight(Float R, Float h, Float mu, Float h_s) {
  Float r = R + h;
  Float b = r * mu;
  Float discriminant = b * b - (h - h_s) * (2.0 * R + h + h_s);
  if (discriminant < 0.0) return -1.0;
  Float t = h_s >= h ? -b + sqrt(discriminant) : -b - sqrt(discriminant);
  return t >= 0.0 ? t : -1.0;
}

#endif
