// The medium and the table sizes of the precomputed atmosphere (Bruneton & Neyret 2008,
// section 2.1; the spectral, ozone-aware form of Bruneton's 2017 reference implementation).
// Lengths in metres, coefficients in m^-1. A vec4 spectrum holds four wavelengths: the C++
// side (physics/atmosphere/) fills one AtmosphereParameters per group of four wavelengths.
#ifndef SKYIG_ATMOSPHERE_PARAMETERS_GLSL
#define SKYIG_ATMOSPHERE_PARAMETERS_GLSL

// Samples of a tabulated aerosol phase function (kMiePhaseSamples in aerosol_type.h).
const int ATMOSPHERE_MIE_PHASE_SAMPLES = 64;

struct AtmosphereParameters {
  // Solar spectral irradiance at the top of the atmosphere, W m^-2 nm^-1.
  vec4 solar_irradiance;
  // Angular radius of the sun disc, radians.
  Float sun_angular_radius;
  // Limb darkening exponent alpha of I(mu)/I(1) = mu^alpha per wavelength (rendering.glsl).
  vec4 limb_darkening_exponent;
  // Radii of the ground sphere and of the top of the atmosphere, m.
  Float bottom_radius;
  Float top_radius;
  // Air molecules: scattering at the ground (= extinction), scale height (eq. 1-2).
  vec4 rayleigh_scattering;
  Float rayleigh_scale_height;
  // Aerosols: scattering and extinction at the ground, scale height, and the phase function:
  // Cornette-Shanks with g when mie_phase_tabulated is 0, else ln p at theta_i = pi (i/(N-1))^2
  // (an OPAC type, aerosol_type.h).
  vec4 mie_scattering;
  vec4 mie_extinction;
  Float mie_scale_height;
  Float mie_phase_g;
  Float mie_phase_tabulated;
  Float mie_phase_log_table[ATMOSPHERE_MIE_PHASE_SAMPLES];
  // Ozone: absorption at the peak density, tent profile (0 at centre - half width, 1 at the
  // centre, 0 at centre + half width).
  vec4 absorption_extinction;
  Float ozone_center_altitude;
  Float ozone_half_width;
  // Lambertian ground reflectance.
  vec4 ground_albedo;
  // Cosine of the largest sun zenith angle the scattering tables cover.
  Float mu_s_min;
  // Table sizes (texels), as Float so GLSL and C++ need no int/float conversions.
  Float transmittance_width;   // mu
  Float transmittance_height;  // r
  Float irradiance_width;      // mu_s
  Float irradiance_height;     // r
  Float scattering_r_size;
  Float scattering_mu_size;    // even: half for rays hitting the ground, half for the others
  Float scattering_mu_s_size;
  Float scattering_nu_size;
};

// Quadrature sample counts (Bruneton 2017 uses the same).
const int ATMOSPHERE_TRANSMITTANCE_SAMPLES = 500;
const int ATMOSPHERE_SINGLE_SCATTERING_SAMPLES = 50;
const int ATMOSPHERE_DENSITY_ANGULAR_SAMPLES = 16;     // per pi, for the scattering density
const int ATMOSPHERE_MULTIPLE_SCATTERING_SAMPLES = 50;
const int ATMOSPHERE_IRRADIANCE_ANGULAR_SAMPLES = 32;  // per pi, for the indirect irradiance

const Float ATMOSPHERE_PI = 3.14159265358979323846;

#endif
