// Uniforms of the physical sky pass's two programs (physical_sky.frag, camera inside the
// atmosphere; physical_sky_space.frag, camera above it): PhysicalSkyPass sets both.
#ifndef SKYIG_PASSES_PHYSICAL_SKY_UNIFORMS_GLSL
#define SKYIG_PASSES_PHYSICAL_SKY_UNIFORMS_GLSL
#include "render/glsl/bindings.h"
#include "physics/atmosphere/rendering_rec709.glsl"
#include "physics/common/refraction.glsl"

uniform AtmosphereParameters atm;
uniform vec3 camera;         // metres from the planet's centre, local frame: x east, y north, z up
uniform vec3 sunDirectionP;  // unit, same frame, airless: lights the sky
// The ephemeris' refraction about the sun's apparent centre (apparent altitude, R, dR/dh,
// d2R/dh2 / 2; radians): where the disc is seen and how it is flattened.
uniform vec4 sunRefraction;
uniform vec3 solarIrradianceXyz;
uniform vec3 limbDarkeningXyz;
uniform float groundAlbedo;
uniform bool moonlightOn;
uniform vec3 moonDirectionP;  // unit, same frame
uniform vec3 moonlightScale;  // Rec.709, the moon's irradiance relative to the sun's
// Per frame, camera inside the atmosphere: radius, rho = sqrt(r^2 - Rg^2), H, u_r, the sun's
// and the moon's u_mu_s (scatteringUvwzFromRMuMuSNu), cos of the sun disc's cone.
uniform vec4 frameRadii;     // r, rho, H, u_r
uniform vec3 frameAngles;    // sun u_mu_s, moon u_mu_s, cos of the cone the refracted sun disc falls in
layout(binding = SKYIG_UNIT_TRANSMITTANCE) uniform sampler2D transmittanceXyz;
layout(binding = SKYIG_UNIT_SCATTERING) uniform sampler3D scatteringPacked;
layout(binding = SKYIG_UNIT_SINGLE_MIE) uniform sampler3D singleMieRG;
layout(binding = SKYIG_UNIT_IRRADIANCE) uniform sampler2D irradianceXyz;

in vec3 vViewRay;
layout(location = SKYIG_OUTPUT_COLOR) out vec4 outRadiance;

#endif
