#pragma once
// Writes a generated dome (calibration/dome.h) as a VESA MPCDI v2.0 file (VESA, "Multiple
// Projection Common Data Interchange", 2015): a zip holding mpcdi.xml and, per projector, its
// geometry warp (PFM), alpha map and beta map (16-bit grey PNG). What calibration/mpcdi.h reads.
//
// One <buffer> per projector holding one <region> that covers it (x = y = 0, xsize = ysize = 1);
// the region's <frustum> is its camera (yaw, pitch, roll; left and down angles negative);
// <coordinateFrame> is the identity with its origin at the eye. Profiles:
// - "2d": the warp's R, G are the (u, v) of the region's image each warp node shows, (0, 0) its
//   top-left corner, v down (B unused, 0); NaN where a node shows nothing.
// - "a3": the warp's R, G, B are the dome point each node lights, in metres from the eyepoint
//   (originOf3DData idealEyePoint), in MPCDI's 3D frame as nDisplay reads it: x right, y up,
//   the forward view along -z.
// The alpha map stores alpha^(1 / gammaEmbedded) (the standard's embedded gamma), the beta map
// the black-level lift in linear light, both at the projector's resolution.
#include "calibration/dome.h"

#include <string>
#include <vector>

namespace skyig::calibration {

enum class MpcdiProfile { TwoD, A3 };

// "2d" / "a3"; CalibrationError naming the word otherwise.
MpcdiProfile parseMpcdiProfile(const std::string& word);

struct MpcdiWriteOptions {
  MpcdiProfile profile = MpcdiProfile::TwoD;
  double gammaEmbedded = 2.2;
};

// mpcdi.xml for the dome's calibrations (generateDome's output, in the dome's projector order).
std::string mpcdiXml(const Dome& dome, const std::vector<ProjectorCalibration>& calibrations,
                     const MpcdiWriteOptions& options);

// The whole .mpcdi zip's bytes. The warp is written on the calibrations' own warp grid (the
// dome's warpStep). CalibrationError when the zip cannot be made.
std::string encodeMpcdi(const Dome& dome, const std::vector<ProjectorCalibration>& calibrations,
                        const MpcdiWriteOptions& options);

// A one-channel map as a 16-bit grey PNG of value^(1 / gamma), values clamped to [0, 1].
std::string encodeGreyPng16(const FloatMap& map, double gamma = 1.0);

}  // namespace skyig::calibration
