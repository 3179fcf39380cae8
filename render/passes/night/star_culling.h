#pragma once
// Which stars and planets a channel can show at all: a source's quad (render/passes/night/star.vert,
// render/passes/night/star_display.vert) lies around its image within a few PSF widths, so a source whose
// image falls farther than that outside the viewport, or behind the eye, touches no pixel. The
// star passes send only the others: a channel of 60 x 50 deg sees a tenth of the 4600 sources
// above the horizon, and llvmpipe runs the vertex stage of every vertex it is sent, four per
// source and three passes a frame. No GL here, so the test can check the bound on the CPU.
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace skyig::render {

// The widest a source's quad can reach from its image, in pixels, in a channel of width x height
// pixels whose view ray is ndcToWorld * (x, y, 1): the larger of the HDR pass's PSF and the
// displayed one (kDisplayedPsfSigmaRad over the smallest pixel, at a corner of a pinhole
// channel), the quad that holds it (starPsfQuadHalfSizePx), and a pixel to spare for float rounding.
double starQuadReachPx(const glm::dmat3& ndcToWorld, int width, int height);

// Whether the quad of a source in ENU direction `direction` may touch the viewport: in front of
// the eye, its image within reachPx of it. worldToNdc is the inverse of ndcToWorld.
inline bool starMayBeInView(const glm::dmat3& worldToNdc, const glm::dvec3& direction, double reachNdcX,
                            double reachNdcY) {
  const glm::dvec3 p = worldToNdc * direction;
  if (!(p.z > 0.0)) return false;
  return p.x <= (1.0 + reachNdcX) * p.z && -p.x <= (1.0 + reachNdcX) * p.z && p.y <= (1.0 + reachNdcY) * p.z &&
         -p.y <= (1.0 + reachNdcY) * p.z;
}

}  // namespace skyig::render
