#ifndef SKYIG_GLSL_EDGE_COVERAGE_GLSL
#define SKYIG_GLSL_EDGE_COVERAGE_GLSL
// Analytic anti-aliasing of an edge the fragment stage computes (the horizon, the terrain's
// line, a disc's limb): the share of the pixel's square on the side where a smooth `value` is
// positive, the box filter's coverage of the edge taken as straight across one pixel. Written
// once for the GPU passes and the CPU tests (render/glsl/edge_coverage.h).

// The area of the unit square centred on the origin where n . p < s, n a unit vector: the
// distribution of the square's projection onto n. With a = max(|n_x|, |n_y|) and
// b = min(|n_x|, |n_y|) the projection spans [-(a + b) / 2, (a + b) / 2]; a line n . p = s
// inside the middle part, |s| <= (a - b) / 2, crosses two opposite sides, so the area grows
// linearly there (slope 1 / a); beyond it the line cuts a corner, a right triangle with legs
// t / a and t / b, t = (a + b) / 2 - |s|: area t^2 / (2 a b).
Float squareShareBelow(Float s, IN(vec2) n) {
  Float a = max(abs(n.x), abs(n.y));
  Float b = min(abs(n.x), abs(n.y));
  Float d = abs(s);
  Float t = clamp(0.5 * (a + b) - d, 0.0, b);
  Float tail = d <= 0.5 * (a - b) ? 0.5 - d / a : t * t / (2.0 * a * max(b, 1e-9));
  return s >= 0.0 ? 1.0 - tail : tail;
}

// The share of a pixel where `value` > 0, given its value at the pixel's centre and its
// gradient in pixels (x, y): the signed distance to the edge is value / |gradient|.
Float pixelShareAbove(Float value, IN(vec2) gradient) {
  Float g = length(gradient);
  if (g <= 0.0) return value > 0.0 ? 1.0 : 0.0;
  return squareShareBelow(value / g, gradient / g);
}

#ifndef SKYIG_GLSL_AS_CPP
// The same with the gradient from the 2 x 2 quad's differences, for a value smooth over a pixel.
float pixelShareAbove(float value) { return pixelShareAbove(value, vec2(dFdx(value), dFdy(value))); }
#endif

#endif
