#pragma once
// A projector as skyig draws for it: the camera its region of the dome asks for, and per
// projector pixel where in that camera's image its light comes from (the geometry warp) and how
// much of it it sends (the alpha blend and beta black-level maps). Read from VESA MPCDI files or
// Paul Bourke's warp meshes (calibration/mpcdi.h, calibration/bourke_mesh.h) or made for a
// spherical dome (calibration/dome.h); the renderer's warp-and-blend pass draws from it.
//
// No GL and no sockets here (docs/design.md, "Layout"): the maps are plain float arrays, the
// cameras the sky's own (sky/camera.h).
#include "sky/camera.h"

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace skyig::calibration {

// The camera of a region: an eyepoint rotation in the body frame (a channel's offset) and the
// half-angles of its frustum, as a channel's camera (sky/camera.h).
struct RegionCamera {
  skyig::sky::Attitude offset;
  skyig::sky::Frustum frustum;
};

// A float image of `channels` values per pixel, rows from the TOP (a PFM's bottom-up rows are
// turned over when read), row-major.
struct FloatMap {
  int width = 0;
  int height = 0;
  int channels = 1;
  std::vector<float> values;

  bool empty() const { return values.empty(); }
  float at(int x, int y, int c = 0) const {
    return values[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) *
                      static_cast<std::size_t>(channels) +
                  static_cast<std::size_t>(c)];
  }
  float& at(int x, int y, int c = 0) {
    return values[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) *
                      static_cast<std::size_t>(channels) +
                  static_cast<std::size_t>(c)];
  }
};

struct ProjectorCalibration {
  std::string source;  // the file (and region) it was read from, for messages
  // What the reader accepted but says, "FILE:LINE: ...", for the node's log.
  std::vector<std::string> warnings;
  std::string region;  // the MPCDI region id (or the mesh's file name)
  int width = 0;       // the projector's pixels
  int height = 0;
  // What to render for it, when the file says (MPCDI 3d, a3, sl); otherwise (MPCDI 2d, a Bourke
  // mesh) the channel's own offset and frustum from the configuration.
  RegionCamera camera;
  bool cameraGiven = false;
  // Per projector pixel (width x height, 2 channels): the point of the camera's image whose
  // light it shows, as (u, v) in [0, 1], u to the right and v DOWN from the image's top-left
  // corner (the display image's own rows); NaN where the projector shows nothing. The warp map
  // may be coarser than the projector (MPCDI's are): the pass interpolates it bilinearly, node
  // (i, j) of a W x H map lying on the projector's pixel centre (i (width-1)/(W-1),
  // j (height-1)/(H-1)), so the first and last nodes sit on the first and last pixels.
  FloatMap warp;
  // Per projector pixel (any size, 1 channel; interpolated): the fraction of its light this
  // projector sends, in LINEAR light (any gamma the file embedded already taken out), so the
  // projectors' alphas over a point of the screen add up to 1. Empty: 1 everywhere.
  FloatMap alpha;
  // Per projector pixel (any size, 1 channel; interpolated): the black-level lift, in linear
  // light as a fraction of the projector's white, added where fewer projectors overlap so the
  // black of a single projector matches the summed black of an overlap. Empty: 0 everywhere.
  FloatMap beta;
};

}  // namespace skyig::calibration
