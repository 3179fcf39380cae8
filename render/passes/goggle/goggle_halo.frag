// The halo (physics/goggle/intensifier.glsl): the photocathode illuminance around each point weighted
// by the halo's Gaussian (Thomas, Allison et al. 2005 model the halo's profile as one), on the
// block means (render/passes/goggle/goggle_pass.h), in two separable passes along uDirection (1, 0)
// then (0, 1), out to 3 sigma. Zero beyond the channel (the sampler's border). The second pass
// writes the natural log: a halo falls by orders of magnitude over a few coarse texels, and read
// bilinearly in log (quadratic in the distance for a Gaussian) its edge stays round where a
// linear read drew the 8-pixel grid.
#include "render/glsl/uniforms.h"
#include "render/glsl/goggle_uniforms.h"

layout(binding = SKYIG_UNIT_GOGGLE_COARSE) uniform sampler2D coarseImage;
uniform vec2 uDirection;
uniform bool uWriteLog;
layout(location = SKYIG_OUTPUT_COLOR) out vec4 outHalo;

void main() {
  vec2 size = vec2(textureSize(coarseImage, 0));
  float sigma = max(goggleCathode.z / goggleCathode.w, 0.3);  // coarse texels
  int reach = int(ceil(3.0 * sigma));
  float sum = 0.0, weights = 0.0;
  for (int i = -reach; i <= reach; ++i) {
    float w = exp(-0.5 * float(i * i) / (sigma * sigma));
    sum += w * textureLod(coarseImage, (gl_FragCoord.xy + float(i) * uDirection) / size, 0.0).r;
    weights += w;
  }
  float halo = sum / weights;
  outHalo = vec4(uWriteLog ? log(max(halo, 1e-30)) : halo, 0.0, 0.0, 1.0);
}
