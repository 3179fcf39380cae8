#include "calibration/dome.h"

#include "calibration/region_camera.h"

#include "calibration/calibration_error.h"
#include "physics/common/units.h"

#include <algorithm>
#include <optional>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace skyig::calibration {

namespace {

using skyig::kDeg;

std::string projectorName(const DomeProjector& p, std::size_t index) {
  return p.name.empty() ? "projector " + std::to_string(index + 1) : "projector '" + p.name + "'";
}

}  // namespace

int warpGridSamples(int pixels, int step) { return pixels <= 1 ? 1 : (pixels - 1 + step - 1) / step + 1; }
double warpGridPixel(int index, int samples, int pixels) {
  return samples <= 1 ? 0.5 : 0.5 + index * static_cast<double>(pixels - 1) / (samples - 1);
}

skyig::sky::Frustum lensFromThrowRatio(double throwRatio, int width, int height, double shiftX, double shiftY) {
  // Image width / throw distance = 1 / throwRatio at the lens's plane x = 1.
  const double halfW = 0.5 / throwRatio, halfH = halfW * height / width;
  const double cx = shiftX * 2.0 * halfW, cy = shiftY * 2.0 * halfH;
  return {std::atan(halfW - cx) / kDeg, std::atan(halfW + cx) / kDeg, std::atan(halfH - cy) / kDeg,
          std::atan(halfH + cy) / kDeg};
}

Dome defaultHelicopterDome(int width, int height) {
  Dome dome;
  // 16:10 images with square pixels: tan(vertical) = tan(horizontal) * 10 / 16.
  const double h = 36.5, v = std::atan(std::tan(h * kDeg) * height / width) / kDeg;
  const skyig::sky::Frustum lens{h, h, v, v};
  // Forward: yaws 60 degrees apart, throw 73 degrees wide, so neighbours share about 12 degrees
  // as seen from the eye. Mounted above and behind the pilot's head.
  const glm::dvec3 mount(-0.4, 0.0, -0.6);
  dome.projectors.push_back({"left", mount + glm::dvec3(0, -0.15, 0), {-60.0, 4.0, 0.0}, lens, width, height});
  dome.projectors.push_back({"centre", mount, {0.0, 4.0, 0.0}, lens, width, height});
  dome.projectors.push_back({"right", mount + glm::dvec3(0, 0.15, 0), {60.0, 4.0, 0.0}, lens, width, height});
  // Chin windows: below the forward row, overlapping it and each other.
  dome.projectors.push_back({"chin-left", mount + glm::dvec3(0.1, -0.1, 0), {-28.0, -38.0, 0.0}, lens, width, height});
  dome.projectors.push_back({"chin-right", mount + glm::dvec3(0.1, 0.1, 0), {28.0, -38.0, 0.0}, lens, width, height});
  return dome;
}

DomeGeometry::DomeGeometry(const Dome& dome) : dome_(dome) {
  if (!(dome.radius > 0.0) || !std::isfinite(dome.radius))
    throw CalibrationError("dome: radius " + std::to_string(dome.radius) + " m is not a positive length");
  if (!(glm::length(dome.eye) < dome.radius)) throw CalibrationError("dome: the eye is not inside the dome");
  for (std::size_t i = 0; i < dome.projectors.size(); ++i) {
    const DomeProjector& p = dome.projectors[i];
    const std::string name = projectorName(p, i);
    if (p.width < 2 || p.height < 2) throw CalibrationError(name + ": resolution " + std::to_string(p.width) + "x" + std::to_string(p.height) + " is too small");
    if (!(glm::length(p.position) < dome.radius)) throw CalibrationError(name + ": it is not inside the dome");
    for (double a : {p.lens.leftDeg, p.lens.rightDeg, p.lens.downDeg, p.lens.upDeg})
      if (!(a > -89.0 && a <= 89.0)) throw CalibrationError(name + ": lens half-angle " + std::to_string(a) + " is outside (-89, 89]");
    if (!(p.lens.leftDeg + p.lens.rightDeg > 0.0 && p.lens.downDeg + p.lens.upDeg > 0.0))
      throw CalibrationError(name + ": the lens has no width or no height");
    const glm::dmat3 m = calibration::ndcToBody(p.orientation, p.lens);  // the member of that name is per projector
    ndcToBody_.push_back(m);
    bodyToNdc_.push_back(glm::inverse(m));
  }
}

PixelPoint DomeGeometry::trace(std::size_t p, double column, double row) const {
  const DomeProjector& pr = dome_.projectors[p];
  const double x = 2.0 * column / pr.width - 1.0, y = 1.0 - 2.0 * row / pr.height;
  const glm::dvec3 ray = glm::normalize(ndcToBody_[p] * glm::dvec3(x, y, 1.0));
  // |position + t ray| = R with the projector inside: one root in front.
  const double b = glm::dot(pr.position, ray);
  const double c = glm::dot(pr.position, pr.position) - dome_.radius * dome_.radius;
  const double disc = b * b - c;
  if (disc < 0.0) return {};
  const double t = -b + std::sqrt(disc);
  if (!(t > 0.0)) return {};
  return {true, pr.position + t * ray};
}

bool DomeGeometry::project(std::size_t p, const glm::dvec3& point, double& column, double& row) const {
  const DomeProjector& pr = dome_.projectors[p];
  const glm::dvec3 q = bodyToNdc_[p] * (point - pr.position);
  if (!(q.z > 0.0)) return false;  // the third component is the distance along the lens axis
  column = (q.x / q.z + 1.0) * 0.5 * pr.width;
  row = (1.0 - q.y / q.z) * 0.5 * pr.height;
  return true;
}

glm::dvec3 DomeGeometry::eyeDirection(const glm::dvec3& point) const { return glm::normalize(point - dome_.eye); }

// Raskar, Welch, Cutts, Lake, Stesin & Fuchs 1998 ("The Office of the Future") weight each
// projector by its pixel's distance to its own image's edge and divide by the sum over the
// projectors lighting the point: a weight that vanishes at the edge makes the alphas
// continuous where an image ends. Two refinements here. A linear ramp still has a kink at the
// overlap's sides, which the eye sees as a Mach band in a smooth sky: the smoothstep
// 3e^2 - 2e^3 has zero slope at the edge and at the centre. And the distance to the NEAREST
// edge, min(ex, ey), has kinks along the image's diagonals, which make the ratio jump where two
// images share an edge (two chin windows ending on one row): the product of one smoothstep per
// axis vanishes at every edge and is smooth everywhere inside. e is in NDC (0 at an edge, 1 at
// the centre), independent of resolution.
double edgeWeight(double xNdc, double yNdc) {
  auto ramp = [](double e) {
    e = std::clamp(e, 0.0, 1.0);
    return e * e * (3.0 - 2.0 * e);
  };
  return ramp(1.0 - std::abs(xNdc)) * ramp(1.0 - std::abs(yNdc));
}

namespace {

void validate(const Dome& dome) {
  if (dome.projectors.empty()) throw CalibrationError("dome: no projectors");
  if (dome.warpStep < 1) throw CalibrationError("dome: warp step " + std::to_string(dome.warpStep) + " is not a positive pixel count");
  if (!(dome.contrast >= 1.0) || !std::isfinite(dome.contrast))
    throw CalibrationError("dome: contrast " + std::to_string(dome.contrast) + " is not a ratio of at least 1");
}

// A projector's warp grid: the dome direction (from the eye) of every sample that meets the dome.
struct WarpGrid {
  int width = 0, height = 0;
  std::vector<glm::dvec3> directions;
  std::vector<bool> hit;
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * static_cast<std::size_t>(width) + static_cast<std::size_t>(i); }
};

WarpGrid traceWarpGrid(const DomeGeometry& geometry, std::size_t p, const DomeProjector& pr, int step) {
  WarpGrid g{warpGridSamples(pr.width, step), warpGridSamples(pr.height, step), {}, {}};
  g.directions.resize(static_cast<std::size_t>(g.width) * static_cast<std::size_t>(g.height));
  g.hit.resize(g.directions.size());
  for (int j = 0; j < g.height; ++j)
    for (int i = 0; i < g.width; ++i) {
      const PixelPoint hit = geometry.trace(p, warpGridPixel(i, g.width, pr.width), warpGridPixel(j, g.height, pr.height));
      g.hit[g.index(i, j)] = hit.hit;
      if (hit.hit) g.directions[g.index(i, j)] = geometry.eyeDirection(hit.point);
    }
  return g;
}

// The directions the projector lights: its warp grid's and its image's border pixels'.
std::vector<glm::dvec3> footprint(const DomeGeometry& geometry, std::size_t p, const DomeProjector& pr, const WarpGrid& grid) {
  std::vector<glm::dvec3> out;
  for (std::size_t k = 0; k < grid.directions.size(); ++k)
    if (grid.hit[k]) out.push_back(grid.directions[k]);
  for (int i = 0; i < pr.width; ++i)
    for (double row : {0.0, static_cast<double>(pr.height)})
      if (auto hit = geometry.trace(p, i + 0.5, row); hit.hit) out.push_back(geometry.eyeDirection(hit.point));
  for (int j = 0; j < pr.height; ++j)
    for (double column : {0.0, static_cast<double>(pr.width)})
      if (auto hit = geometry.trace(p, column, j + 0.5); hit.hit) out.push_back(geometry.eyeDirection(hit.point));
  return out;
}

// Where each warp sample's light comes from in the region camera's image; NaN where none does.
FloatMap warpOf(const RegionCamera& camera, const WarpGrid& grid) {
  FloatMap warp{grid.width, grid.height, 2, std::vector<float>(grid.directions.size() * 2, std::nanf(""))};
  for (int j = 0; j < grid.height; ++j)
    for (int i = 0; i < grid.width; ++i) {
      const std::size_t k = grid.index(i, j);
      const auto uv = grid.hit[k] ? uvOfDirection(camera, grid.directions[k]) : std::nullopt;
      if (uv && uv->x >= 0.0 && uv->x <= 1.0 && uv->y >= 0.0 && uv->y <= 1.0) {
        warp.at(i, j, 0) = static_cast<float>(uv->x);
        warp.at(i, j, 1) = static_cast<float>(uv->y);
      }
    }
  return warp;
}

// One pixel's blend: its projector's edge weight over the sum of every lighting projector's,
// and how many projectors light its dome point.
struct PixelBlend {
  float alpha = 0.0f;
  int count = 0;
};

PixelBlend blendAt(const Dome& dome, const DomeGeometry& geometry, std::size_t p, const glm::dvec3& point) {
  double own = 0.0, sum = 0.0;
  int count = 0;
  for (std::size_t q = 0; q < dome.projectors.size(); ++q) {
    double column = 0.0, row = 0.0;
    if (!geometry.project(q, point, column, row)) continue;
    const DomeProjector& pq = dome.projectors[q];
    const double x = 2.0 * column / pq.width - 1.0, y = 1.0 - 2.0 * row / pq.height;
    if (std::abs(x) >= 1.0 || std::abs(y) >= 1.0) continue;
    const double w = edgeWeight(x, y);
    ++count;
    sum += w;
    if (q == p) own = w;
  }
  return {sum > 0.0 ? static_cast<float>(own / sum) : 1.0f, count};
}

// The arc (degrees) between two projectors' camera axes, seen from the eye, on which both light
// the dome, in 0.05 degree steps; nothing when they share no step.
std::optional<double> sharedArcDeg(const Dome& dome, const DomeGeometry& geometry, const std::vector<ProjectorCalibration>& out,
                    std::size_t a, std::size_t c) {
  const glm::dvec3 da = directionOfUv(out[a].camera, {0.5, 0.5}), dc = directionOfUv(out[c].camera, {0.5, 0.5});
  const double arc = std::acos(std::clamp(glm::dot(da, dc), -1.0, 1.0));
  const int steps = std::max(1, static_cast<int>(arc / (0.05 * kDeg)));
  auto lights = [&](std::size_t q, const glm::dvec3& point) {
    double column = 0.0, row = 0.0;
    return geometry.project(q, point, column, row) && column > 0.0 && column < dome.projectors[q].width && row > 0.0 &&
           row < dome.projectors[q].height;
  };
  int shared = 0;
  for (int s = 0; s <= steps; ++s) {
    const double t = static_cast<double>(s) / steps;
    const glm::dvec3 dir = arc > 1e-9 ? glm::normalize(std::sin((1 - t) * arc) * da + std::sin(t * arc) * dc) : da;
    // The dome point in that direction from the eye.
    const double bb = glm::dot(dome.eye, dir), cc = glm::dot(dome.eye, dome.eye) - dome.radius * dome.radius;
    const glm::dvec3 point = dome.eye + (-bb + std::sqrt(bb * bb - cc)) * dir;
    if (lights(a, point) && lights(c, point)) ++shared;
  }
  if (shared == 0) return std::nullopt;
  return shared * arc / steps / kDeg;
}

void summarize(const Dome& dome, const DomeGeometry& geometry, const std::vector<ProjectorCalibration>& out,
               const std::vector<std::vector<std::uint8_t>>& lightCount, int kMax, DomeSummary& summary) {
  const std::size_t n = out.size();
  summary.maxOverlap = kMax;
  summary.minAlpha.assign(n, 1.0);
  summary.maxAlpha.assign(n, 0.0);
  for (std::size_t p = 0; p < n; ++p)
    for (std::size_t k = 0; k < out[p].alpha.values.size(); ++k)
      if (lightCount[p][k] > 0) {
        summary.minAlpha[p] = std::min(summary.minAlpha[p], static_cast<double>(out[p].alpha.values[k]));
        summary.maxAlpha[p] = std::max(summary.maxAlpha[p], static_cast<double>(out[p].alpha.values[k]));
      }
  summary.overlaps.clear();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t c = a + 1; c < n; ++c)
      if (const std::optional<double> arcDeg = sharedArcDeg(dome, geometry, out, a, c))
        summary.overlaps.push_back({a, c, *arcDeg});
}

}  // namespace

std::vector<ProjectorCalibration> generateDome(const Dome& dome, DomeSummary* summary,
                                               const std::function<void(double)>& progress) {
  validate(dome);
  const DomeGeometry geometry(dome);
  const std::size_t n = dome.projectors.size();
  std::size_t totalPixels = 0;
  for (const auto& p : dome.projectors) totalPixels += static_cast<std::size_t>(p.width) * static_cast<std::size_t>(p.height);
  std::size_t donePixels = 0;
  auto report = [&](std::size_t add) {
    donePixels += add;
    if (progress) progress(static_cast<double>(donePixels) / static_cast<double>(2 * totalPixels));
  };

  std::vector<ProjectorCalibration> out(n);
  std::vector<std::vector<std::uint8_t>> lightCount(n);
  int kMax = 0;
  for (std::size_t p = 0; p < n; ++p) {
    const DomeProjector& pr = dome.projectors[p];
    ProjectorCalibration& cal = out[p];
    cal.region = pr.name;
    cal.source = "generated dome, region " + pr.name;
    cal.width = pr.width;
    cal.height = pr.height;
    const WarpGrid grid = traceWarpGrid(geometry, p, pr, dome.warpStep);
    const std::vector<glm::dvec3> lit = footprint(geometry, p, pr, grid);
    if (lit.empty()) throw CalibrationError(projectorName(pr, p) + ": none of its pixels meets the dome");
    cal.camera = cameraCovering(lit, glm::normalize(geometry.ndcToBody(p)[0]), dome.marginDeg, projectorName(pr, p));
    cal.warp = warpOf(cal.camera, grid);
    cal.alpha = {pr.width, pr.height, 1, std::vector<float>(static_cast<std::size_t>(pr.width) * static_cast<std::size_t>(pr.height), 0.0f)};
    lightCount[p].assign(cal.alpha.values.size(), 0);
    for (int j = 0; j < pr.height; ++j) {
      for (int i = 0; i < pr.width; ++i) {
        const PixelPoint hit = geometry.trace(p, i + 0.5, j + 0.5);
        if (!hit.hit) continue;
        const PixelBlend blend = blendAt(dome, geometry, p, hit.point);
        const std::size_t k = static_cast<std::size_t>(j) * static_cast<std::size_t>(pr.width) + static_cast<std::size_t>(i);
        cal.alpha.values[k] = blend.alpha;
        lightCount[p][k] = static_cast<std::uint8_t>(std::min(blend.count, 255));
        kMax = std::max(kMax, blend.count);
      }
      report(static_cast<std::size_t>(pr.width));
    }
  }

  // Beta: lift each point's black to the summed black of the deepest overlap, shared among the
  // projectors lighting it by their alphas, b = 1 / contrast.
  const double b = 1.0 / dome.contrast;
  for (std::size_t p = 0; p < n; ++p) {
    ProjectorCalibration& cal = out[p];
    cal.beta = {cal.width, cal.height, 1, std::vector<float>(cal.alpha.values.size(), 0.0f)};
    for (std::size_t k = 0; k < cal.alpha.values.size(); ++k)
      if (lightCount[p][k] > 0) cal.beta.values[k] = static_cast<float>(static_cast<double>(cal.alpha.values[k]) * b * (kMax - lightCount[p][k]));
    report(cal.alpha.values.size());
  }
  if (summary) summarize(dome, geometry, out, lightCount, kMax, *summary);
  if (progress) progress(1.0);
  return out;
}

}  // namespace skyig::calibration
