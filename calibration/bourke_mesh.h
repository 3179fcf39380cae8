#pragma once
// Paul Bourke's warp mesh (the text format of his planetarium and fisheye-projection tools,
// read by many dome players): a first line with the mesh type (2: a rectangular grid), then
// "NX NY", then NX x NY lines "x y u v i": x, y the node's place on the projector in its
// normalised coordinates (x from -aspect to aspect, y from -1 at the bottom to 1 at the top),
// u, v the point of the rendered image it shows (OpenGL texture coordinates, v up), i the
// brightness to send there (0 to 1; a negative i: the node shows nothing). Nodes run along x
// first, from the bottom row up.
//
// A mesh names no camera: the channel's own offset and frustum render the image. Its intensity
// is taken as linear light (the fraction of the projector's light sent), as skyig blends in
// light.
#include "calibration/projector.h"

#include <string>

namespace skyig::calibration {

// The mesh as a projector of `width` x `height` pixels (the channel's size). Throws
// CalibrationError naming the file and line: an unknown mesh type, a bad count, a short or
// non-numeric line, nodes that are not a rectangular grid.
ProjectorCalibration readBourkeMesh(const std::string& path, int width, int height);

}  // namespace skyig::calibration
