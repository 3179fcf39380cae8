#pragma once
// A calibration made from geometry, for CI and for new users before their projection vendor's
// tool has run: a spherical dome, the pilot's eyepoint, and pinhole projectors at known
// positions and orientations. For every projector pixel the ray from the projector through it
// hits the dome at P; the direction from the eye to P is what that pixel must show. It is a
// starting point, never a replacement for a measured calibration (docs/projectors.md).
//
// Frames: skyig's body frame (x forward, y right, z down; metres from the dome's centre), angles
// as sky/camera.h (yaw, pitch, roll in degrees). Cameras and projector lenses are the sky's
// cameras (sky::ndcToWorld): one camera model for channels, regions and projectors.
#include "calibration/projector.h"

#include <functional>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace skyig::calibration {

struct DomeProjector {
  std::string name;                    // the MPCDI region id
  glm::dvec3 position{0.0, 0.0, 0.0};  // body frame, metres from the dome's centre
  skyig::sky::Attitude orientation;    // the lens axis, as a channel's eyepoint offset
  // The throw as half-angles of the lens's frustum; an asymmetric frustum is a lens shift.
  skyig::sky::Frustum lens;
  int width = 1920;
  int height = 1200;
};

// The lens of a projector given by its throw ratio (throw distance / image width) and lens
// shift (fractions of the image's width and height, positive right and up), square pixels.
skyig::sky::Frustum lensFromThrowRatio(double throwRatio, int width, int height, double shiftX = 0.0,
                                       double shiftY = 0.0);

struct Dome {
  double radius = 3.0;             // metres
  glm::dvec3 eye{0.0, 0.0, 0.0};   // the pilot's eyepoint, body frame, metres from the centre
  double contrast = 2000.0;        // projector white / projector black (beta's b = 1/contrast)
  int warpStep = 1;                // warp samples every warpStep-th projector pixel (and the last)
  double marginDeg = 1.0;          // added to each side of a region camera's frustum
  std::vector<DomeProjector> projectors;
};

// The helicopter dome `skyig dome` writes by default: radius 3 m, eye at the centre, three
// projectors forward side by side (overlaps of about 12 degrees) and two chin windows below,
// each `width` x `height`.
Dome defaultHelicopterDome(int width = 1920, int height = 1200);

// Where a projector's ray meets the dome. Image points of a projector are (column, row) with
// pixel (i, j)'s centre at (i + 0.5, j + 0.5), rows from the top.
struct PixelPoint {
  bool hit = false;        // the ray meets the dome in front of the projector
  glm::dvec3 point{0.0};   // where on the dome (body frame)
};

// The geometry the generator and its tests share.
class DomeGeometry {
 public:
  explicit DomeGeometry(const Dome& dome);
  const Dome& dome() const { return dome_; }
  // Where the ray of projector p through the image point (column, row) meets the dome.
  PixelPoint trace(std::size_t p, double column, double row) const;
  // Where the dome point `point` falls in projector p's image (column, row as trace); false
  // when behind the projector's lens. The image is [0, width] x [0, height].
  bool project(std::size_t p, const glm::dvec3& point, double& column, double& row) const;
  // The unit direction from the eye to `point`, body frame.
  glm::dvec3 eyeDirection(const glm::dvec3& point) const;
  // Projector p's lens as a matrix: (x_ndc, y_ndc, 1) -> body-frame ray (sky::ndcToWorld).
  const glm::dmat3& ndcToBody(std::size_t p) const { return ndcToBody_[p]; }

 private:
  Dome dome_;
  std::vector<glm::dmat3> ndcToBody_;  // projector p: (x_ndc, y_ndc, 1) -> body ray
  std::vector<glm::dmat3> bodyToNdc_;
};

// A region camera's image and directions: calibration/region_camera.h (uvOfDirection,
// directionOfUv), the same for the generator, the readers and the tests.

// What the generator found besides the calibrations, for `skyig dome` to print.
struct DomeSummary {
  int maxOverlap = 0;  // k_max: the most projectors lighting one dome point
  struct Overlap {
    std::size_t a, b;
    double degrees;  // along the arc (from the eye) between the two footprints' centres
  };
  std::vector<Overlap> overlaps;
  std::vector<double> minAlpha, maxAlpha;  // per projector, over its lit pixels
};

// Computes every projector's calibration: the region camera covering its footprint as seen
// from the eye (plus the margin), the warp (every warpStep-th pixel and the last, the first and
// last samples on the first and last pixels' centres), alpha and beta at the projector's
// resolution. Throws CalibrationError when the dome is impossible (a projector outside the
// dome, a footprint wider than a camera can cover, bad sizes). `progress` gets fractions in
// [0, 1].
std::vector<ProjectorCalibration> generateDome(const Dome& dome, DomeSummary* summary = nullptr,
                                               const std::function<void(double)>& progress = {});

// The warp grid across `pixels` projector pixels with a sample every `step`-th pixel and on the
// last: how many samples, and the pixel coordinate (as DomeGeometry::trace) of sample `index`.
// Samples are evenly spaced from the first pixel's centre to the last's, which is how the warp
// pass reads a map coarser than the projector (render/passes/projector/warp_blend.frag).
int warpGridSamples(int pixels, int step);
double warpGridPixel(int index, int samples, int pixels);

// The blend weight of a point of a projector's image at NDC (x, y): the product of smoothsteps
// of its distances to the image's vertical and horizontal edges (see dome.cpp for why).
double edgeWeight(double xNdc, double yNdc);

}  // namespace skyig::calibration
