#include "calibration/bourke_mesh.h"

#include "calibration/calibration_error.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace skyig::calibration {

ProjectorCalibration readBourkeMesh(const std::string& path, int width, int height) {
  std::ifstream in(path);
  if (!in) throw CalibrationError(path + ": cannot open the warp mesh");
  int lineNumber = 0;
  std::string line;
  const auto next = [&](const char* what) {
    while (std::getline(in, line)) {
      ++lineNumber;
      if (line.find_first_not_of(" \t\r") != std::string::npos) return;
    }
    throw CalibrationError(path + ":" + std::to_string(lineNumber) + ": the file ends before " + what);
  };
  next("the mesh type");
  int type = 0;
  {
    std::istringstream s(line);
    if (!(s >> type) || type != 2)
      throw CalibrationError(path + ":" + std::to_string(lineNumber) + ": mesh type \"" + line +
                             "\": expected 2 (a rectangular grid; polar meshes are not read)");
  }
  next("the mesh size");
  int nx = 0, ny = 0;
  {
    std::istringstream s(line);
    if (!(s >> nx >> ny) || nx < 2 || ny < 2 || nx > 8192 || ny > 8192)
      throw CalibrationError(path + ":" + std::to_string(lineNumber) + ": mesh size \"" + line +
                             "\": expected two node counts from 2 to 8192");
  }
  ProjectorCalibration p;
  p.source = path;
  p.region = path;
  p.width = width;
  p.height = height;
  p.warp = {nx, ny, 2, std::vector<float>(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) * 2)};
  p.alpha = {nx, ny, 1, std::vector<float>(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny))};
  std::vector<double> xs(static_cast<std::size_t>(nx)), ys(static_cast<std::size_t>(ny));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      next("all the nodes the size promises");
      std::istringstream s(line);
      double x, y, u, v, intensity;
      // Bounded so that every value fits the float maps (a larger one has no meaning on a
      // projector or in an image, and converting it to float would overflow).
      const auto bounded = [](double value) { return std::isfinite(value) && std::abs(value) <= 1e6; };
      if (!(s >> x >> y >> u >> v >> intensity) || !bounded(x) || !bounded(y) || !bounded(u) || !bounded(v) ||
          !bounded(intensity))
        throw CalibrationError(path + ":" + std::to_string(lineNumber) + ": node \"" + line +
                               "\": expected five numbers x y u v intensity, each within +-1e6");
      // The grid must be rectangular: one x per column and one y per row.
      const double tolerance = 1e-4;
      if (j == 0) xs[static_cast<std::size_t>(i)] = x;
      if (i == 0) ys[static_cast<std::size_t>(j)] = y;
      if (std::abs(x - xs[static_cast<std::size_t>(i)]) > tolerance || std::abs(y - ys[static_cast<std::size_t>(j)]) > tolerance)
        throw CalibrationError(path + ":" + std::to_string(lineNumber) + ": node (" + std::to_string(i) + ", " +
                               std::to_string(j) + ") at x " + std::to_string(x) + " y " + std::to_string(y) +
                               " is off the rectangular grid the first row and column set");
      const int row = ny - 1 - j;  // the file runs from the bottom row up
      const bool shown = intensity >= 0.0;
      p.warp.at(i, row, 0) = shown ? static_cast<float>(u) : std::numeric_limits<float>::quiet_NaN();
      p.warp.at(i, row, 1) = shown ? static_cast<float>(1.0 - v) : std::numeric_limits<float>::quiet_NaN();  // v up -> down
      p.alpha.at(i, row) = shown ? static_cast<float>(std::min(intensity, 1.0)) : 0.0f;
    }
  if (!(xs.back() > xs.front()) || !(ys.back() > ys.front()))
    throw CalibrationError(path + ": the nodes must run left to right and bottom to top");
  return p;
}

}  // namespace skyig::calibration
