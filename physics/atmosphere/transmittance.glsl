// Transmittance T(r, mu) from a point to the top of the atmosphere, its 2D table and the
// derived transmittances (Bruneton & Neyret 2008, section 4 "Precomputation": T(x, y) =
// T(x, v) / T(y, v) for any y on the ray from x along v). The table holds the optical depth
// tau(r, mu), not T = exp(-tau) as Bruneton's does: along the horizon of a 0.5 km fog tau is
// about 860, and exp(-860) is below even double precision (float fails past tau = 87-103, a
// 3-5 km haze). The ratio of two transmittances is then exp(-(tau(x) - tau(y))): no underflow,
// no 0 / 0.
#ifndef SKYIG_ATMOSPHERE_TRANSMITTANCE_GLSL
#define SKYIG_ATMOSPHERE_TRANSMITTANCE_GLSL
#include "physics/atmosphere/geometry.glsl"
#include "physics/atmosphere/medium.glsl"

// Optical depth (extinction integrated along the ray) from (r, mu) to the top of the
// atmosphere, per wavelength; trapezoidal rule (Bruneton & Neyret 2008, eq. 5).
vec4 opticalDepthToTopAtmosphereBoundary(IN(AtmosphereParameters) atm, Float r, Float mu) {
  Float dx = distanceToTopAtmosphereBoundary(atm, r, mu) /
             Float(ATMOSPHERE_TRANSMITTANCE_SAMPLES);
  Float rayleigh_length = 0.0;
  Float mie_length = 0.0;
  Float ozone_length = 0.0;
  for (int i = 0; i <= ATMOSPHERE_TRANSMITTANCE_SAMPLES; ++i) {
    Float d_i = Float(i) * dx;
    Float altitude = sqrt(d_i * d_i + 2.0 * r * mu * d_i + r * r) - atm.bottom_radius;
    Float weight = (i == 0 || i == ATMOSPHERE_TRANSMITTANCE_SAMPLES) ? 0.5 : 1.0;
    rayleigh_length += rayleighDensity(atm, altitude) * weight * dx;
    mie_length += mieDensity(atm, altitude) * weight * dx;
    ozone_length += ozoneDensity(atm, altitude) * weight * dx;
  }
  return atm.rayleigh_scattering * rayleigh_length + atm.mie_extinction * mie_length +
         atm.absorption_extinction * ozone_length;
}

// Table coordinates (Bruneton 2017, after Bruneton & Neyret 2008 section 4): x_r = rho / H
// with rho the distance to the horizon and H its value at the top; x_mu the distance to the
// top mapped linearly between its smallest (r straight up) and largest (horizon) values.
vec2 transmittanceUvFromRMu(IN(AtmosphereParameters) atm, Float r, Float mu) {
  Float H = sqrt(atm.top_radius * atm.top_radius - atm.bottom_radius * atm.bottom_radius);
  Float rho = atmSafeSqrt(r * r - atm.bottom_radius * atm.bottom_radius);
  Float d = distanceToTopAtmosphereBoundary(atm, r, mu);
  Float d_min = atm.top_radius - r;
  Float d_max = rho + H;
  Float x_mu = (d - d_min) / (d_max - d_min);
  Float x_r = rho / H;
  return vec2(textureCoordFromUnitRange(x_mu, atm.transmittance_width),
              textureCoordFromUnitRange(x_r, atm.transmittance_height));
}

void rMuFromTransmittanceUv(IN(AtmosphereParameters) atm, IN(vec2) uv, OUT(Float) r,
                            OUT(Float) mu) {
  Float x_mu = unitRangeFromTextureCoord(uv.x, atm.transmittance_width);
  Float x_r = unitRangeFromTextureCoord(uv.y, atm.transmittance_height);
  Float H = sqrt(atm.top_radius * atm.top_radius - atm.bottom_radius * atm.bottom_radius);
  Float rho = H * x_r;
  r = sqrt(rho * rho + atm.bottom_radius * atm.bottom_radius);
  Float d_min = atm.top_radius - r;
  Float d_max = rho + H;
  Float d = d_min + x_mu * (d_max - d_min);
  mu = d == 0.0 ? 1.0 : (H * H - rho * rho - d * d) / (2.0 * r * d);
  mu = atmClampCosine(mu);
}

// Value of the texel whose centre is frag_coord (in texels), the precomputation's kernel: the
// optical depth to the top of the atmosphere, per wavelength.
vec4 computeOpticalDepthTexel(IN(AtmosphereParameters) atm, IN(vec2) frag_coord) {
  Float r;
  Float mu;
  rMuFromTransmittanceUv(
      atm, vec2(frag_coord.x / atm.transmittance_width, frag_coord.y / atm.transmittance_height),
      r, mu);
  return opticalDepthToTopAtmosphereBoundary(atm, r, mu);
}

// Bilinear interpolation with the weights in full precision. A GPU's texture unit filters with
// 8 fractional bits of weight (NVIDIA's CUDA guide, "Linear Filtering": 1/256 steps), which an
// optical depth does not survive: between two texels of depths 28 and 30 it is off by up to
// 0.004, 0.4% of the light through them. The CPU's texture() is exact already.
vec4 textureBilinearExact(IN(sampler2D) t, IN(vec2) uv) {
#ifdef SKYIG_GLSL_AS_CPP
  return texture(t, uv);
#else
  ivec2 size = textureSize(t, 0);
  vec2 p = uv * vec2(size) - vec2(0.5);
  vec2 base = floor(p);
  vec2 f = p - base;
  ivec2 i0 = clamp(ivec2(base), ivec2(0), size - ivec2(1));
  ivec2 i1 = clamp(ivec2(base) + ivec2(1), ivec2(0), size - ivec2(1));
  return mix(mix(texelFetch(t, i0, 0), texelFetch(t, ivec2(i1.x, i0.y), 0), f.x),
             mix(texelFetch(t, ivec2(i0.x, i1.y), 0), texelFetch(t, i1, 0), f.x), f.y);
#endif
}

// The table's optical depth to the top of the atmosphere (linear interpolation of tau, which
// is linear in the aerosol extinction: blends of visibility steps stay exact).
vec4 tabulatedOpticalDepth(IN(AtmosphereParameters) atm, IN(sampler2D) transmittance_texture,
                           Float r, Float mu) {
  return textureBilinearExact(transmittance_texture, transmittanceUvFromRMu(atm, r, mu));
}

vec4 transmittanceToTopAtmosphereBoundary(IN(AtmosphereParameters) atm,
                                          IN(sampler2D) transmittance_texture, Float r,
                                          Float mu) {
  return exp(-tabulatedOpticalDepth(atm, transmittance_texture, r, mu));
}

// exp(-(tau_far - tau_near)) of a segment whose optical depths to the top are tau_near (its end
// nearer the top) and tau_far; never above one (the two lookups interpolate independently).
vec4 transmittanceOfDifference(IN(vec4) tau_far, IN(vec4) tau_near) {
  return exp(-max(tau_far - tau_near, vec4(0.0)));
}

// Transmittance between (r, mu) and the point at distance d along the ray, from the difference
// of two lookups of the optical depth to the top (Bruneton 2017, GetTransmittance, which divides
// the two transmittances). A ray that hits the ground is looked up reversed (-mu), so neither
// lookup crosses the ground. A ray that dips (mu < 0) and rises again without meeting it is
// split at its lowest point: up to there the segment is looked up reversed from each end, two
// upward rays through thin air; beyond, it is the segment to the lowest point plus the one from
// there (horizontal) on. The plain difference tau(r_d, mu_d) - tau(r, mu) would subtract two
// depths that both hold the densest air at the lowest point and lose its digits to rounding.
vec4 transmittanceAlongRay(IN(AtmosphereParameters) atm, IN(sampler2D) transmittance_texture,
                           Float r, Float mu, Float d, bool ray_r_mu_intersects_ground) {
  Float r_d = radiusAtDistance(atm, r, mu, d);
  Float mu_d = atmClampCosine((r * mu + d) / r_d);
  if (ray_r_mu_intersects_ground || (mu < 0.0 && mu_d <= 0.0)) {
    return transmittanceOfDifference(
        tabulatedOpticalDepth(atm, transmittance_texture, r_d, -mu_d),
        tabulatedOpticalDepth(atm, transmittance_texture, r, -mu));
  }
  if (mu < 0.0) {
    Float r_low = atmClampRadius(atm, r * sqrt(max(1.0 - mu * mu, 0.0)));
    vec4 low = tabulatedOpticalDepth(atm, transmittance_texture, r_low, 0.0);
    return transmittanceOfDifference(low, tabulatedOpticalDepth(atm, transmittance_texture, r, -mu)) *
           transmittanceOfDifference(low, tabulatedOpticalDepth(atm, transmittance_texture, r_d, mu_d));
  }
  return transmittanceOfDifference(tabulatedOpticalDepth(atm, transmittance_texture, r, mu),
                                   tabulatedOpticalDepth(atm, transmittance_texture, r_d, mu_d));
}

// Transmittance of sunlight to radius r, times the visible fraction of the sun disc above the
// horizon (linear in the sun elevation across the disc; Bruneton 2017).
vec4 transmittanceToSun(IN(AtmosphereParameters) atm, IN(sampler2D) transmittance_texture,
                        Float r, Float mu_s) {
  Float sin_theta_h = atm.bottom_radius / r;
  Float cos_theta_h = -sqrt(max(1.0 - sin_theta_h * sin_theta_h, 0.0));
  return transmittanceToTopAtmosphereBoundary(atm, transmittance_texture, r, mu_s) *
         smoothstep(-sin_theta_h * atm.sun_angular_radius, sin_theta_h * atm.sun_angular_radius,
                    mu_s - cos_theta_h);
}

#endif
