#include "calibration/mpcdi_writer.h"

#include "calibration/calibration_error.h"
#include "calibration/pfm.h"
#include "calibration/png_map.h"

#include <tinyxml2.h>
#include <zip.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>

namespace skyig::calibration {

namespace {

std::string number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

void textChild(tinyxml2::XMLPrinter& out, const char* name, const std::string& text) {
  out.OpenElement(name);
  out.PushText(text.c_str());
  out.CloseElement();
}

std::string fileName(const ProjectorCalibration& cal, const char* what) { return cal.region + "_" + what; }

// Body frame (x forward, y right, z down) to the axes the a3 points are written in: OpenGL's,
// x right, y up, forward along -z. The coordinateFrame written with them says so explicitly
// (calibration/mpcdi.h: its yaw, pitch and roll vectors are the down, right and forward axes),
// so a reader that follows the frame and one that assumes OpenGL's axes read the same points.
glm::dvec3 bodyToMpcdi(const glm::dvec3& b) { return {b.y, -b.z, -b.x}; }

// The a3 warp: the dome point each warp node lights, from the eye.
FloatMap pointsWarp(const DomeGeometry& geometry, std::size_t p, const FloatMap& grid) {
  const DomeProjector& pr = geometry.dome().projectors[p];
  FloatMap out{grid.width, grid.height, 3,
               std::vector<float>(static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height) * 3,
                                  std::numeric_limits<float>::quiet_NaN())};
  for (int j = 0; j < grid.height; ++j)
    for (int i = 0; i < grid.width; ++i) {
      if (!std::isfinite(grid.at(i, j, 0))) continue;
      const PixelPoint hit = geometry.trace(p, warpGridPixel(i, grid.width, pr.width), warpGridPixel(j, grid.height, pr.height));
      if (!hit.hit) continue;
      const glm::dvec3 m = bodyToMpcdi(hit.point - geometry.dome().eye);
      for (int c = 0; c < 3; ++c) out.at(i, j, c) = static_cast<float>(m[c]);
    }
  return out;
}

FloatMap imageWarp(const FloatMap& grid) {
  FloatMap out{grid.width, grid.height, 3, std::vector<float>(grid.values.size() / 2 * 3, 0.0f)};
  for (int j = 0; j < grid.height; ++j)
    for (int i = 0; i < grid.width; ++i) {
      out.at(i, j, 0) = grid.at(i, j, 0);
      out.at(i, j, 1) = grid.at(i, j, 1);
    }
  return out;
}


}  // namespace

MpcdiProfile parseMpcdiProfile(const std::string& word) {
  if (word == "2d") return MpcdiProfile::TwoD;
  if (word == "a3") return MpcdiProfile::A3;
  throw CalibrationError("MPCDI profile \"" + word + "\": the dome writes 2d or a3");
}

std::string encodeGreyPng16(const FloatMap& map, double gamma) {
  if (map.channels != 1 || map.width < 1 || map.height < 1) throw CalibrationError("PNG: not a one-channel map");
  FloatMap stored = map;  // value^(1/gamma): MPCDI's gammaEmbedded
  for (float& v : stored.values) v = static_cast<float>(std::pow(std::clamp(static_cast<double>(v), 0.0, 1.0), 1.0 / gamma));
  const std::vector<std::uint8_t> png = writePngMap16(stored);
  return std::string(png.begin(), png.end());
}

std::string mpcdiXml(const Dome& dome, const std::vector<ProjectorCalibration>& calibrations,
                     const MpcdiWriteOptions& options) {
  const bool a3 = options.profile == MpcdiProfile::A3;
  tinyxml2::XMLPrinter out;
  out.PushHeader(false, true);
  out.OpenElement("MPCDI");
  out.PushAttribute("profile", a3 ? "a3" : "2d");
  out.PushAttribute("geometry", "1");
  out.PushAttribute("color", "1");
  out.PushAttribute("version", "2.0");
  out.OpenElement("display");
  for (const ProjectorCalibration& cal : calibrations) {
    out.OpenElement("buffer");
    out.PushAttribute("id", cal.region.c_str());
    out.PushAttribute("xResolution", cal.width);
    out.PushAttribute("yResolution", cal.height);
    out.OpenElement("region");
    out.PushAttribute("id", cal.region.c_str());
    out.PushAttribute("xResolution", cal.width);
    out.PushAttribute("yResolution", cal.height);
    out.PushAttribute("x", "0");
    out.PushAttribute("y", "0");
    out.PushAttribute("xsize", "1");
    out.PushAttribute("ysize", "1");
    out.OpenElement("frustum");
    textChild(out, "yaw", number(cal.camera.offset.yawDeg));
    textChild(out, "pitch", number(cal.camera.offset.pitchDeg));
    textChild(out, "roll", number(cal.camera.offset.rollDeg));
    textChild(out, "rightAngle", number(cal.camera.frustum.rightDeg));
    textChild(out, "leftAngle", number(-cal.camera.frustum.leftDeg));
    textChild(out, "upAngle", number(cal.camera.frustum.upDeg));
    textChild(out, "downAngle", number(-cal.camera.frustum.downDeg));
    out.CloseElement();
    // The 3D data's frame: its origin the eyepoint; down (the yaw axis) is -y, right (the pitch
    // axis) +x, forward (the roll axis) -z, as bodyToMpcdi writes the points.
    out.OpenElement("coordinateFrame");
    const double frame[4][3] = {{0, 0, 0}, {0, -1, 0}, {1, 0, 0}, {0, 0, -1}};
    const char* names[4] = {"pos", "yaw", "pitch", "roll"};
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < 3; ++c) textChild(out, (std::string(names[a]) + "xyz"[c]).c_str(), number(frame[a][c]));
    out.CloseElement();
    out.CloseElement();  // region
    out.CloseElement();  // buffer
  }
  out.CloseElement();  // display
  out.OpenElement("files");
  for (const ProjectorCalibration& cal : calibrations) {
    out.OpenElement("fileset");
    out.PushAttribute("region", cal.region.c_str());
    out.OpenElement("geometryWarpFile");
    textChild(out, "path", fileName(cal, "warp.pfm"));
    textChild(out, "interpolation", "linear");
    if (a3) {
      textChild(out, "geometricUnit", "m");
      textChild(out, "originOf3DData", "idealEyePoint");
    }
    out.CloseElement();
    out.OpenElement("alphaMap");
    textChild(out, "path", fileName(cal, "alpha.png"));
    textChild(out, "componentDepth", "1");
    textChild(out, "bitDepth", "16");
    textChild(out, "gammaEmbedded", number(options.gammaEmbedded));
    out.CloseElement();
    out.OpenElement("betaMap");
    textChild(out, "path", fileName(cal, "beta.png"));
    textChild(out, "componentDepth", "1");
    textChild(out, "bitDepth", "16");
    out.CloseElement();
    out.CloseElement();  // fileset
  }
  out.CloseElement();  // files
  out.CloseElement();  // MPCDI
  (void)dome;
  return out.CStr();
}

std::string encodeMpcdi(const Dome& dome, const std::vector<ProjectorCalibration>& calibrations,
                        const MpcdiWriteOptions& options) {
  if (calibrations.size() != dome.projectors.size()) throw CalibrationError("MPCDI: calibrations do not match the dome");
  const DomeGeometry geometry(dome);
  // Every file's bytes live until zip_close reads them.
  std::vector<std::pair<std::string, std::string>> files;
  files.emplace_back("mpcdi.xml", mpcdiXml(dome, calibrations, options));
  for (std::size_t p = 0; p < calibrations.size(); ++p) {
    const ProjectorCalibration& cal = calibrations[p];
    const FloatMap warp = options.profile == MpcdiProfile::A3 ? pointsWarp(geometry, p, cal.warp) : imageWarp(cal.warp);
    const std::vector<std::uint8_t> pfm = writePfm(warp);
    files.emplace_back(fileName(cal, "warp.pfm"), std::string(pfm.begin(), pfm.end()));
    files.emplace_back(fileName(cal, "alpha.png"), encodeGreyPng16(cal.alpha, options.gammaEmbedded));
    files.emplace_back(fileName(cal, "beta.png"), encodeGreyPng16(cal.beta, 1.0));
  }

  zip_error_t error;
  zip_error_init(&error);
  auto fail = [&](const std::string& what) {
    const std::string message = "MPCDI zip: " + what + " (" + zip_error_strerror(&error) + ")";
    zip_error_fini(&error);
    throw CalibrationError(message);
  };
  zip_source_t* buffer = zip_source_buffer_create(nullptr, 0, 0, &error);
  if (buffer == nullptr) fail("no memory buffer");
  zip_source_keep(buffer);
  std::unique_ptr<zip_source_t, decltype(&zip_source_free)> keep(buffer, &zip_source_free);
  zip_t* archive = zip_open_from_source(buffer, ZIP_TRUNCATE, &error);
  if (archive == nullptr) fail("cannot open an archive in memory");
  for (const auto& [name, bytes] : files) {
    zip_source_t* s = zip_source_buffer(archive, bytes.data(), bytes.size(), 0);
    if (s == nullptr || zip_file_add(archive, name.c_str(), s, ZIP_FL_ENC_UTF_8) < 0) {
      if (s) zip_source_free(s);
      zip_error_set(&error, zip_error_code_zip(zip_get_error(archive)), 0);
      zip_discard(archive);
      fail("cannot add " + name);
    }
  }
  if (zip_close(archive) < 0) {
    zip_error_set(&error, zip_error_code_zip(zip_get_error(archive)), 0);
    zip_discard(archive);
    fail("cannot finish the archive");
  }
  std::string out;
  if (zip_source_open(buffer) < 0) fail("cannot read the archive back");
  char chunk[65536];
  for (;;) {
    const zip_int64_t n = zip_source_read(buffer, chunk, sizeof chunk);
    if (n < 0) {
      zip_source_close(buffer);
      fail("cannot read the archive back");
    }
    if (n == 0) break;
    out.append(chunk, static_cast<std::size_t>(n));
  }
  zip_source_close(buffer);
  zip_error_fini(&error);
  return out;
}

}  // namespace skyig::calibration
