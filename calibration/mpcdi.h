#pragma once
// VESA Multiple Projection Common Data Interchange (MPCDI) v2, 2015: the XML that describes a
// display as buffers of regions (one region = one projector), each with its frustum and
// coordinate frame, and per region a file set: the geometry warp (PFM), the alpha blend map
// (PNG, with the gamma embedded in it), the beta (black level) map (PNG) and, in the advanced
// profiles, a distortion map (PFM).
//
// Profiles (the root's `profile` attribute):
//   2d  2D media: the warp maps projector pixels to (x, y) of the region's content; no frustum
//       (the channel's own camera from the configuration renders the content).
//   3d  3D simulation: as 2d, and the region's frustum is the camera to render.
//   a3  advanced 3D: the warp holds 3D points of the screen (x, y, z in the coordinate frame);
//       the pixel shows the direction from the eyepoint (the coordinate frame's position) to its
//       point, seen through the region's frustum.
//   sl  shader lamps: 3D points as a3, seen from the frame's origin (the frame's position is the
//       projector's pose there, not an eye).
//
// Frames. The standard's frustum turns the view by yaw (positive to the right), then pitch
// (positive up), then roll (positive: right wing down) -- CIGI's order and signs, so they are
// the region camera's offset unchanged. Its angles are signed (leftAngle and downAngle usually
// negative): the frustum's half-angles are -leftAngle, rightAngle, -downAngle, upAngle. The
// coordinate frame gives, in the file's axes, the unit vectors of the yaw axis (down), the
// pitch axis (right) and the roll axis (forward) of the standard's aircraft figure: a 3D point
// p is at (roll.p, pitch.p, yaw.p) in skyig's body frame (x forward, y right, z down). Without
// a coordinateFrame the file's axes are taken as OpenGL's (y up, -z forward, x right).
//
// 2D warp values: readers in the wild disagree whether a PFM node holds the ABSOLUTE content
// coordinate or its OFFSET from the node's own place on the grid; both are read, named by
// WarpValues. Content coordinates are (x right, y down) from the region's top-left in [0, 1].
#include "calibration/projector.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace skyig::calibration {

class MpcdiArchive;

enum class WarpValues { Absolute, Offset };

struct MpcdiFileRef {
  std::string path;  // empty: not given
  int line = 0;      // of its element in the XML
};

struct MpcdiRegion {
  std::string id;
  std::string buffer;
  int line = 0;
  int xResolution = 0;
  int yResolution = 0;
  bool hasFrustum = false;
  RegionCamera camera;
  bool hasFrame = false;
  glm::dvec3 position{0.0};
  glm::dvec3 yawAxis{0.0, -1.0, 0.0};  // OpenGL's axes when the file gives none
  glm::dvec3 pitchAxis{1.0, 0.0, 0.0};
  glm::dvec3 rollAxis{0.0, 0.0, -1.0};
  MpcdiFileRef warp, alpha, beta, distortion;
  double alphaGammaEmbedded = 1.0;
  // What is wrong with this region alone (its resolution, frustum, frame or file set), "FILE:LINE:
  // ...": loading it throws this, while the file's other regions load.
  std::string error;
};

struct MpcdiDescription {
  std::string profile;  // "2d", "3d", "a3" or "sl"
  std::vector<MpcdiRegion> regions;
  // What was read but looks wrong, "FILE:LINE: ...": said, not refused.
  std::vector<std::string> warnings;
  const MpcdiRegion* find(const std::string& id) const;
  std::string regionIds() const;  // "r1, r2, r3", for messages
};

// Parses the XML (`name` for messages). Throws CalibrationError naming the file, the line and
// the element: malformed XML, an unknown profile, a region without a resolution, a frustum with
// a missing, non-finite or impossible angle, a file set for a region that does not exist.
MpcdiDescription parseMpcdiXml(const std::vector<std::uint8_t>& xml, const std::string& name);

// The description of an MPCDI file (zip, folder or XML), for tools and tests that list its
// regions.
MpcdiDescription readMpcdi(const std::string& path);

// Region `id` of the archive as a projector: its camera, its warp turned into the channel's
// image coordinates, its blend maps in linear light. Throws CalibrationError naming the file
// and element: no such region (the ids there are listed), a warp or map that cannot be read or
// whose size does not fit the region.
ProjectorCalibration readMpcdiRegion(const MpcdiArchive& archive, const MpcdiDescription& description,
                                     const std::string& id, WarpValues values);

}  // namespace skyig::calibration
