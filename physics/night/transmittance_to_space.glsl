#ifndef SKYIG_NIGHT_TRANSMITTANCE_TO_SPACE_GLSL
#define SKYIG_NIGHT_TRANSMITTANCE_TO_SPACE_GLSL
// The observer's transmittance to space along a view (linear Rec.709), from the extinction
// profile's 1D table (render/passes/common/extinction_texture.h, physics/atmosphere/extinction_profile.h):
// what the light from beyond the atmosphere keeps. GPU only (a sampler). The diffuse night
// pass (render/passes/night/night_diffuse.frag) and the physical sky pass adding the night's layer
// (render/passes/sky/physical_sky.frag, SKYIG_NIGHT_LAYER) read it alike.

// u = (1 + sign(e) sqrt(|e| / 90 deg)) / 2 for the elevation e: fine steps at the horizon.
float extinctionTexCoord(float elevation) {
  return 0.5 * (1.0 + sign(elevation) * sqrt(abs(elevation) / (0.5 * 3.14159265358979)));
}

vec3 transmittanceToSpace(sampler1D table, vec3 unitView) {
  return max(texture(table, extinctionTexCoord(asin(clamp(unitView.z, -1.0, 1.0)))).rgb, vec3(0.0));
}

#endif
