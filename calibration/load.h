#pragma once
// The projector a channel names in the configuration ([channel.projector]), read in one call
// so the node, `render` and the tests load calibrations the same way.
#include "calibration/calibration_error.h"
#include "calibration/mpcdi.h"
#include "calibration/projector.h"

#include <string>
#include <utility>

namespace skyig::calibration {

struct ProjectorSource {
  std::string mpcdiPath;  // an MPCDI file (zip, folder or XML) ...
  std::string region;     // ... and the region of it
  WarpValues warpValues = WarpValues::Absolute;
  std::string bourkeMeshPath;  // or a Bourke warp mesh ...
  int bourkeWidth = 0;         // ... shown on a projector of this many pixels
  int bourkeHeight = 0;
};

inline ProjectorSource mpcdiSource(std::string path, std::string region, WarpValues values = WarpValues::Absolute) {
  ProjectorSource s;
  s.mpcdiPath = std::move(path);
  s.region = std::move(region);
  s.warpValues = values;
  return s;
}
inline ProjectorSource bourkeSource(std::string path, int width, int height) {
  ProjectorSource s;
  s.bourkeMeshPath = std::move(path);
  s.bourkeWidth = width;
  s.bourkeHeight = height;
  return s;
}

// Throws CalibrationError (the file, where in it, the value).
ProjectorCalibration loadProjector(const ProjectorSource& source);

}  // namespace skyig::calibration
