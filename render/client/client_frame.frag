// The client-frame composite: the channel's image rendered at the client viewport's size, copied
// texel for texel (no filtering: the channel and the viewport have the same pixels). The source
// is either the tone-mapped display frame (display-referred output) or the HDR image in cd/m^2
// (linear output for the client's own tone mapping). Alpha is 1: the sky is opaque.
#include "render/glsl/bindings.h"

layout(binding = SKYIG_UNIT_HOST_SOURCE) uniform sampler2D hostSource;
// The client viewport's lower-left corner in window pixels.
uniform ivec2 viewportOrigin;
layout(location = SKYIG_OUTPUT_COLOR) out vec4 outColor;

void main() {
  outColor = vec4(texelFetch(hostSource, ivec2(gl_FragCoord.xy) - viewportOrigin, 0).rgb, 1.0);
}
