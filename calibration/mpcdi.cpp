#include "calibration/mpcdi.h"

#include "calibration/calibration_error.h"
#include "calibration/mpcdi_archive.h"
#include "calibration/pfm.h"
#include "calibration/png_map.h"
#include "calibration/region_camera.h"

#include <glm/glm.hpp>
#include <tinyxml2.h>

#include <cmath>
#include <strings.h>
#include <cstdlib>
#include <limits>

namespace skyig::calibration {

namespace {

using tinyxml2::XMLElement;

// "mpcdi.xml:12: <region id="r1"> <frustum> <yaw>: "
struct Where {
  std::string file;
  std::string path;
  std::string at(const XMLElement* e) const {
    return file + ":" + std::to_string(e ? e->GetLineNum() : 0) + ": " + path;
  }
  Where in(const XMLElement* e, const std::string& label = "") const {
    return {file, path + "<" + std::string(e->Name()) + (label.empty() ? "" : " " + label) + "> "};
  }
};

[[noreturn]] void fail(const Where& w, const XMLElement* e, const std::string& what) {
  throw CalibrationError(w.at(e) + what);
}

double number(const Where& w, const XMLElement* parent, const char* name, bool required, double fallback = 0.0) {
  const XMLElement* e = parent->FirstChildElement(name);
  if (!e) {
    if (required) fail(w, parent, "<" + std::string(name) + "> missing");
    return fallback;
  }
  const char* text = e->GetText();
  char* end = nullptr;
  const double v = text ? std::strtod(text, &end) : std::numeric_limits<double>::quiet_NaN();
  while (end && *end && std::isspace(static_cast<unsigned char>(*end))) ++end;
  if (!text || *end != '\0' || !std::isfinite(v))
    fail(w.in(e), e, std::string("expected a finite number, got \"") + (text ? text : "") + "\"");
  return v;
}

// An attribute by its name in any letter case: the standard writes xResolution, VESA's reference
// library (the MPCDI SDK) writes and reads Xresolution, and other tools write xresolution.
const char* attributeAnyCase(const XMLElement* e, const char* name) {
  if (const char* exact = e->Attribute(name)) return exact;
  for (const tinyxml2::XMLAttribute* a = e->FirstAttribute(); a; a = a->Next())
    if (strcasecmp(a->Name(), name) == 0) return a->Value();
  return nullptr;
}

int resolution(const Where& w, const XMLElement* e, const char* name) {
  const char* text = attributeAnyCase(e, name);
  if (!text) fail(w, e, std::string(name) + " missing");
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (*end != '\0' || v < 2 || v > 16384)
    fail(w, e, std::string(name) + ": expected a number of pixels from 2 to 16384, got \"" + text + "\"");
  return static_cast<int>(v);
}

RegionCamera readFrustum(const Where& w, const XMLElement* f) {
  RegionCamera c;
  c.offset.yawDeg = number(w, f, "yaw", true);
  c.offset.pitchDeg = number(w, f, "pitch", true);
  c.offset.rollDeg = number(w, f, "roll", true);
  const double left = number(w, f, "leftAngle", true), right = number(w, f, "rightAngle", true);
  const double up = number(w, f, "upAngle", true), down = number(w, f, "downAngle", true);
  for (const double a : {left, right, up, down})
    if (std::abs(a) >= 89.0) fail(w, f, "an angle of " + std::to_string(a) + " degrees: each must lie within +-89");
  if (!(right > left)) fail(w, f, "rightAngle " + std::to_string(right) + " is not to the right of leftAngle " + std::to_string(left));
  if (!(up > down)) fail(w, f, "upAngle " + std::to_string(up) + " is not above downAngle " + std::to_string(down));
  c.frustum = {-left, right, -down, up};
  return c;
}

glm::dvec3 unitVector(const Where& w, const XMLElement* frame, const std::string& axis) {
  const glm::dvec3 v(number(w, frame, (axis + "x").c_str(), true), number(w, frame, (axis + "y").c_str(), true),
                     number(w, frame, (axis + "z").c_str(), true));
  if (std::abs(glm::length(v) - 1.0) > 1e-3) fail(w, frame, "the " + axis + " axis is not a unit vector");
  return v;
}

MpcdiFileRef fileRef(const Where& w, const XMLElement* set, const char* name) {
  const XMLElement* e = set->FirstChildElement(name);
  if (!e) return {};
  const XMLElement* p = e->FirstChildElement("path");
  if (!p || !p->GetText() || std::string(p->GetText()).empty()) fail(w.in(e), e, "<path> missing or empty");
  std::string path = p->GetText();
  while (!path.empty() && std::isspace(static_cast<unsigned char>(path.back()))) path.pop_back();
  while (!path.empty() && std::isspace(static_cast<unsigned char>(path.front()))) path.erase(path.begin());
  return {path, e->GetLineNum()};
}

}  // namespace

const MpcdiRegion* MpcdiDescription::find(const std::string& id) const {
  for (const auto& r : regions)
    if (r.id == id) return &r;
  return nullptr;
}

std::string MpcdiDescription::regionIds() const {
  std::string ids;
  for (const auto& r : regions) ids += (ids.empty() ? "" : ", ") + r.id;
  return ids.empty() ? "none" : ids;
}

namespace {

// A <fileset>'s files and the alpha map's embedded gamma, into its region.
void readFileSet(const Where& ws, const XMLElement* s, MpcdiRegion& region, std::vector<std::string>& warnings) {
  region.warp = fileRef(ws, s, "geometryWarpFile");
  region.alpha = fileRef(ws, s, "alphaMap");
  region.beta = fileRef(ws, s, "betaMap");
  region.distortion = fileRef(ws, s, "distortionMap");
  const XMLElement* a = s->FirstChildElement("alphaMap");
  if (!a) return;
  region.alphaGammaEmbedded = number(ws.in(a), a, "gammaEmbedded", false, 1.0);
  if (region.alphaGammaEmbedded == 0.0) {
    // The MPCDI SDK writes 0 for a member never set, and its own reader ignores the value.
    const XMLElement* g = a->FirstChildElement("gammaEmbedded");
    warnings.push_back(ws.in(a).file + ":" + std::to_string(g->GetLineNum()) + ": region \"" + region.id +
                       "\": <gammaEmbedded> 0 read as not given (no gamma in the alpha map)");
    region.alphaGammaEmbedded = 1.0;
  }
  if (region.alphaGammaEmbedded < 0.1 || region.alphaGammaEmbedded > 10.0)
    fail(ws.in(a), a->FirstChildElement("gammaEmbedded"),
         "<gammaEmbedded> " + std::to_string(region.alphaGammaEmbedded) + " is not a gamma from 0.1 to 10");
}

}  // namespace

MpcdiDescription parseMpcdiXml(const std::vector<std::uint8_t>& xml, const std::string& name) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(reinterpret_cast<const char*>(xml.data()), xml.size()) != tinyxml2::XML_SUCCESS)
    throw CalibrationError(name + ":" + std::to_string(doc.ErrorLineNum()) + ": malformed XML: " + doc.ErrorStr());
  const XMLElement* root = doc.FirstChildElement("MPCDI");
  if (!root) throw CalibrationError(name + ": no <MPCDI> root element (is it an MPCDI file?)");
  const Where top{name, "<MPCDI> "};
  MpcdiDescription d;
  const char* profile = root->Attribute("profile");
  d.profile = profile ? profile : "";
  if (d.profile != "2d" && d.profile != "3d" && d.profile != "a3" && d.profile != "sl")
    fail({name, ""}, root, "<MPCDI profile=\"" + d.profile + "\">: expected the profile 2d, 3d, a3 or sl");
  const bool needsFrustum = d.profile != "2d";
  // a3 and sl warps hold the screen's points: without a frustum the camera that covers them is
  // made from them (readMpcdiRegion), as the reference library's a3 example needs.
  const bool pointsProfile = d.profile == "a3" || d.profile == "sl";
  const XMLElement* display = root->FirstChildElement("display");
  if (!display) fail(top, root, "<display> missing");
  for (const XMLElement* b = display->FirstChildElement("buffer"); b; b = b->NextSiblingElement("buffer")) {
    const char* bufferId = b->Attribute("id");
    const Where wb = top.in(display).in(b, std::string("id=\"") + (bufferId ? bufferId : "") + "\"");
    for (const XMLElement* r = b->FirstChildElement("region"); r; r = r->NextSiblingElement("region")) {
      MpcdiRegion region;
      const char* id = r->Attribute("id");
      if (!id || !*id) fail(wb, r, "<region> without an id");
      region.id = id;
      region.buffer = bufferId ? bufferId : "";
      region.line = r->GetLineNum();
      const Where wr = wb.in(r, "id=\"" + region.id + "\"");
      if (d.find(region.id)) fail(wr, r, "a second region with this id");
      // A region's own values: a problem here is this region's, not its neighbours'.
      try {
        region.xResolution = resolution(wr, r, "xResolution");
        region.yResolution = resolution(wr, r, "yResolution");
        if (const XMLElement* f = r->FirstChildElement("frustum")) {
          region.camera = readFrustum(wr.in(f), f);
          region.hasFrustum = true;
        } else if (needsFrustum && !pointsProfile) {
          fail(wr, r, "<frustum> missing: profile " + d.profile + " renders each region through its frustum");
        } else if (needsFrustum) {
          d.warnings.push_back(wr.file + ":" + std::to_string(region.line) + ": region \"" + region.id +
                               "\": no <frustum>: its camera is made to cover the region's points");
        }
        if (const XMLElement* c = r->FirstChildElement("coordinateFrame")) {
          const Where wc = wr.in(c);
          region.position = {number(wc, c, "posx", true), number(wc, c, "posy", true), number(wc, c, "posz", true)};
          region.yawAxis = unitVector(wc, c, "yaw");
          region.pitchAxis = unitVector(wc, c, "pitch");
          region.rollAxis = unitVector(wc, c, "roll");
          region.hasFrame = true;
        }
      } catch (const CalibrationError& e) {
        region.error = e.what();
      }
      d.regions.push_back(region);
    }
  }
  if (d.regions.empty()) fail(top.in(display), display, "no <buffer><region> in the display");
  if (const XMLElement* files = root->FirstChildElement("files")) {
    for (const XMLElement* s = files->FirstChildElement("fileset"); s; s = s->NextSiblingElement("fileset")) {
      const char* regionId = s->Attribute("region");
      const Where ws = top.in(files).in(s, std::string("region=\"") + (regionId ? regionId : "") + "\"");
      MpcdiRegion* region = nullptr;
      for (auto& r : d.regions)
        if (regionId && r.id == regionId) region = &r;
      if (!region) fail(ws, s, "names no region of the display (there are: " + d.regionIds() + ")");
      try {  // a bad file set refuses its own region only
        readFileSet(ws, s, *region, d.warnings);
      } catch (const CalibrationError& e) {
        if (region->error.empty()) region->error = e.what();
      }
    }
  }
  return d;
}

MpcdiDescription readMpcdi(const std::string& path) {
  const MpcdiArchive archive(path);
  return parseMpcdiXml(archive.xml(), archive.describe(archive.xmlName()));
}

namespace {

// What a warp's nodes show of the region's image. NaN marks a node that shows nothing, by
// design; a warp none of whose nodes lands on the image (NaN, infinite or 3e38 everywhere), or
// all of whose nodes land on one point (absolute values read in the wrong byte order can all
// become tiny floats: every node at the image's corner), is a damaged file, not a calibration. A node within half an image of it
// counts (a blend's margin).
struct WarpCoverage {
  std::size_t onImage = 0;
  glm::dvec2 low{std::numeric_limits<double>::infinity()}, high{-std::numeric_limits<double>::infinity()};
  void add(const glm::dvec2& uv) {
    if (uv.x < -0.5 || uv.x > 1.5 || uv.y < -0.5 || uv.y > 1.5) return;
    ++onImage;
    low = glm::min(low, uv);
    high = glm::max(high, uv);
  }
  void check(const std::string& name, std::size_t nodes, std::vector<std::string>& warnings) const {
    if (onImage == 0)
      throw CalibrationError(name + ": none of the warp's " + std::to_string(nodes) +
                             " nodes lands on the image (NaN, infinite or far outside at every node): a damaged file");
    if (onImage > 1 && glm::all(glm::lessThan(high - low, glm::dvec2(1e-6))))
      throw CalibrationError(name + ": every node of the warp lands on one point (" + std::to_string(low.x) + ", " +
                             std::to_string(low.y) + "): a damaged file, or floats read in the wrong byte order "
                             "(a PFM's negative scale means little-endian)");
    if (2 * onImage < nodes)
      warnings.push_back(name + ": " + std::to_string(nodes - onImage) + " of the warp's " + std::to_string(nodes) +
                         " nodes show nothing of the image");
  }
};

// A warp's coordinates are image fractions or metres: a file most of whose non-zero values lie
// beyond 1e-10..1e10 in magnitude holds no warp. Floats read in the wrong byte order look so:
// a swapped float's exponent comes from the original's low mantissa bits, spread over the range.
void checkMagnitudes(const FloatMap& raw, const std::string& name) {
  std::size_t nonZero = 0, implausible = 0;
  for (const float v : raw.values) {
    if (!std::isfinite(v) || v == 0.0f) continue;
    ++nonZero;
    if (std::abs(v) < 1e-10f || std::abs(v) > 1e10f) ++implausible;
  }
  if (2 * implausible > nonZero)
    throw CalibrationError(name + ": " + std::to_string(implausible) + " of its " + std::to_string(nonZero) +
                           " non-zero values lie outside 1e-10..1e10 in magnitude: not a warp (floats in the wrong "
                           "byte order? a PFM's negative scale means little-endian)");
}

// The camera of an a3 or sl region the file gives no frustum for: it covers the warp's points
// as the eye sees them, 1 degree of margin, its right along the warp's rows (the projector's
// raster), as `skyig dome` makes its regions' cameras (cameraCovering).
template <class BodyPoint>
RegionCamera cameraOfPoints(const FloatMap& raw, const BodyPoint& bodyPoint, const std::string& name) {
  std::vector<glm::dvec3> directions;
  glm::dvec3 along(0.0);
  for (int y = 0; y < raw.height; ++y)
    for (int x = 0; x < raw.width; ++x) {
      const glm::dvec3 b = bodyPoint(x, y);
      if (!(glm::length(b) > 0.0) || !std::isfinite(glm::length(b))) continue;
      directions.push_back(glm::normalize(b));
      if (x + 1 < raw.width) {
        const glm::dvec3 next = bodyPoint(x + 1, y);
        if (std::isfinite(glm::length(next))) along += next - b;
      }
    }
  return cameraCovering(directions, along, 1.0, name + " (a region without a <frustum>)");
}

}  // namespace

ProjectorCalibration readMpcdiRegion(const MpcdiArchive& archive, const MpcdiDescription& d, const std::string& id,
                                     WarpValues values) {
  const MpcdiRegion* region = d.find(id);
  const std::string xml = archive.describe(archive.xmlName());
  if (!region) throw CalibrationError(xml + ": no region \"" + id + "\" (the file has: " + d.regionIds() + ")");
  if (!region->error.empty()) throw CalibrationError(region->error);
  const std::string at = xml + ":" + std::to_string(region->line) + ": region \"" + id + "\": ";
  if (region->warp.path.empty()) throw CalibrationError(at + "no <fileset> with a <geometryWarpFile> for it");
  ProjectorCalibration p;
  p.source = archive.path() + " region " + id;
  for (const std::string& w : d.warnings)
    if (w.find("region \"" + id + "\"") != std::string::npos) p.warnings.push_back(w);
  p.region = id;
  p.width = region->xResolution;
  p.height = region->yResolution;
  p.camera = region->camera;

  // What a region can need, checked before a file is read or a map decoded: a hostile file (a
  // PNG whose header says 60000 x 60000, a zip member that inflates to gigabytes, a padded PFM)
  // is refused by its size, not after the memory is gone.
  const std::uint64_t pixels = static_cast<std::uint64_t>(p.width) * static_cast<std::uint64_t>(p.height);
  const std::uint64_t maxPfmBytes = 4096 + pixels * 3 * sizeof(float);
  const std::uint64_t maxPngBytes = (std::uint64_t{1} << 20) + pixels * 8 + static_cast<std::uint64_t>(p.height);
  const std::string warpName = archive.describe(region->warp.path);
  const FloatMap raw = readPfm(archive.read(region->warp.path, maxPfmBytes, "a warp of region \"" + id + "\""), warpName);
  if (raw.width < 2 || raw.height < 2 || raw.width > p.width || raw.height > p.height)
    throw CalibrationError(warpName + ": a " + std::to_string(raw.width) + "x" + std::to_string(raw.height) +
                           " warp does not fit region \"" + id + "\" of " + std::to_string(p.width) + "x" +
                           std::to_string(p.height) + " pixels (at least 2x2, at most the region's resolution)");
  checkMagnitudes(raw, warpName);
  const bool points = d.profile == "a3" || d.profile == "sl";
  if (points && raw.channels != 3)
    throw CalibrationError(warpName + ": profile " + d.profile + " needs 3D points (a PF file of 3 channels), this has 1");
  FloatMap distortion;
  if (!region->distortion.path.empty()) {
    const std::string name = archive.describe(region->distortion.path);
    distortion = readPfm(archive.read(region->distortion.path, maxPfmBytes, "a distortion map of region \"" + id + "\""), name);
    if (distortion.width != raw.width || distortion.height != raw.height || distortion.channels != 3)
      throw CalibrationError(name + ": the distortion map must match the warp (" + std::to_string(raw.width) + "x" +
                             std::to_string(raw.height) + ", PF), it is " + std::to_string(distortion.width) + "x" +
                             std::to_string(distortion.height) + "x" + std::to_string(distortion.channels));
  }
  WarpCoverage shown;
  p.warp.width = raw.width;
  p.warp.height = raw.height;
  p.warp.channels = 2;
  p.warp.values.assign(static_cast<std::size_t>(raw.width) * static_cast<std::size_t>(raw.height) * 2,
                       std::numeric_limits<float>::quiet_NaN());
  const glm::dvec3 eye = d.profile == "a3" ? region->position : glm::dvec3(0.0);
  // A node's point in the body frame (x forward, y right, z down), seen from the eye.
  const auto bodyPoint = [&](int x, int y) {
    const glm::dvec3 q = glm::dvec3(raw.at(x, y, 0), raw.at(x, y, 1), raw.at(x, y, 2)) - eye;
    return glm::dvec3(glm::dot(q, region->rollAxis), glm::dot(q, region->pitchAxis), glm::dot(q, region->yawAxis));
  };
  if (points && !region->hasFrustum) p.camera = cameraOfPoints(raw, bodyPoint, warpName);
  // The warp's image coordinates are the camera's: the file's frustum, or the one made for its
  // points; a 2d region without one is drawn through the channel's own.
  p.cameraGiven = region->hasFrustum || points;
  for (int y = 0; y < raw.height; ++y)
    for (int x = 0; x < raw.width; ++x) {
      glm::dvec2 uv;
      if (points) {
        const glm::dvec3 body = bodyPoint(x, y);
        if (!std::isfinite(body.x) || !std::isfinite(body.y) || !std::isfinite(body.z)) continue;
        const auto seen = uvOfDirection(p.camera, body);
        if (!seen) continue;  // behind the eye: nothing to show
        uv = *seen;
      } else {
        uv = {raw.at(x, y, 0), raw.at(x, y, 1)};
        if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) continue;
        if (values == WarpValues::Offset)
          uv += glm::dvec2(static_cast<double>(x) / (raw.width - 1), static_cast<double>(y) / (raw.height - 1));
      }
      if (!distortion.empty()) uv += glm::dvec2(distortion.at(x, y, 0), distortion.at(x, y, 1));
      // Far outside the image (a point nearly at right angles to the camera): nothing shown, and
      // no float overflow.
      if (!(std::abs(uv.x) <= 1e6 && std::abs(uv.y) <= 1e6)) continue;
      p.warp.at(x, y, 0) = static_cast<float>(uv.x);
      p.warp.at(x, y, 1) = static_cast<float>(uv.y);
      shown.add(uv);
    }
  shown.check(warpName, static_cast<std::size_t>(raw.width) * static_cast<std::size_t>(raw.height), p.warnings);

  const auto blendMap = [&](const MpcdiFileRef& ref, const char* what) {
    if (ref.path.empty()) return FloatMap{};
    const std::string name = archive.describe(ref.path);
    FloatMap m = readPngMap(archive.read(ref.path, maxPngBytes, std::string("a 16-bit RGBA ") + what + " of region \"" + id + "\""),
                            name, p.width, p.height);
    if (m.width < 2 || m.height < 2 || m.width > p.width || m.height > p.height)
      throw CalibrationError(name + ": a " + std::to_string(m.width) + "x" + std::to_string(m.height) + " " + what +
                             " does not fit region \"" + id + "\" of " + std::to_string(p.width) + "x" +
                             std::to_string(p.height) + " pixels");
    return m;
  };
  p.alpha = blendMap(region->alpha, "alpha map");
  // The alpha map was stored with a gamma in it (MPCDI's gammaEmbedded) so that it multiplies
  // gamma-encoded pixels; in light it is the stored value raised to that gamma.
  for (float& a : p.alpha.values) a = static_cast<float>(std::pow(static_cast<double>(a), region->alphaGammaEmbedded));
  p.beta = blendMap(region->beta, "beta map");
  return p;
}

}  // namespace skyig::calibration
