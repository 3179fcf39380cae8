// One triangle covering the viewport (Wang, Ji & Zhang 2011, section 4: no sky dome mesh).
// Each vertex carries the view ray through it, the inverse projection of eq. 22; the ray is
// affine in screen space, so interpolating it is exact.
#include "render/glsl/uniforms.h"

out vec3 vViewRay;
out vec2 vTexCoord;

void main() {
  vec2 ndc = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
  vViewRay = mat3(ndcToWorld) * vec3(ndc, 1.0);
  vTexCoord = ndc * 0.5 + 0.5;
  gl_Position = vec4(ndc, 0.0, 1.0);
}
