// The dome generator (calibration/dome.h) against its own geometry, traced independently here:
// a dome point seen by two projectors shows one sky direction, the alphas add up to 1, beta
// levels the black floor, and each projector lights where its frustum says.
#include "calibration/dome.h"
#include "calibration/region_camera.h"

#include "calibration/calibration_error.h"
#include "physics/common/units.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace {

using skyig::calibration::Dome;
using skyig::calibration::DomeGeometry;
using skyig::calibration::DomeSummary;
using skyig::calibration::FloatMap;
using skyig::calibration::ProjectorCalibration;

using skyig::kDeg;

// The generated default helicopter dome at full resolution with the MPCDI-sized warp grid
// (every 8th pixel), made once for every test of the suite.
struct Generated {
  Dome dome;
  std::vector<ProjectorCalibration> calibrations;
  DomeSummary summary;
};
const Generated& generated() {
  static const Generated g = [] {
    Generated out;
    out.dome = skyig::calibration::defaultHelicopterDome();
    out.dome.warpStep = 8;
    out.calibrations = skyig::calibration::generateDome(out.dome, &out.summary);
    return out;
  }();
  return g;
}

// Bilinear read of a map whose first and last samples sit on the first and last pixels' centres
// (as the warp pass reads it), at the projector's image point (column, row).
double sampleMap(const FloatMap& map, int width, int height, double column, double row, int channel) {
  const double sx = std::clamp((column - 0.5) * (map.width - 1) / (width - 1), 0.0, map.width - 1.0);
  const double sy = std::clamp((row - 0.5) * (map.height - 1) / (height - 1), 0.0, map.height - 1.0);
  const int x0 = std::min(static_cast<int>(sx), map.width - 2), y0 = std::min(static_cast<int>(sy), map.height - 2);
  const double fx = sx - x0, fy = sy - y0;
  auto at = [&](int x, int y) { return static_cast<double>(map.at(x, y, channel)); };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) + fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

struct Sight {
  std::size_t projector;
  double column, row;
  double edge;  // pixels to the nearest edge of this projector's image
};

// Where the lit dome ends, every projector's weight vanishes and their ratio (alpha) turns fast
// within a few pixels (the corners where two images' outer edges cross; up to 0.4% off 1 there,
// interpolated): the blend is judged where some projector lighting the point is at least this
// many pixels inside its image.
constexpr double kInsideTheLitDome = 16.0;
bool insideTheLitDome(const std::vector<Sight>& sights) {
  return std::any_of(sights.begin(), sights.end(), [](const Sight& s) { return s.edge >= kInsideTheLitDome; });
}

// The dome points on a 0.5 degree grid of directions from the eye, each with the projectors
// whose images contain it, at least `inset` pixels inside their edges; `nearAnEdge` when some
// projector's edge is closer than `inset` (where beta steps and the interpolated maps mix).
template <typename F>
void forEachDomePoint(const Generated& g, double inset, F&& visit) {
  const DomeGeometry geometry(g.dome);
  for (double el = -89.5; el <= 89.5; el += 0.5)
    for (double az = -180.0; az < 180.0; az += 0.5) {
      // Body frame: x forward, y right, z down.
      const glm::dvec3 dir(std::cos(el * kDeg) * std::cos(az * kDeg), std::cos(el * kDeg) * std::sin(az * kDeg),
                           -std::sin(el * kDeg));
      const double b = glm::dot(g.dome.eye, dir), c = glm::dot(g.dome.eye, g.dome.eye) - g.dome.radius * g.dome.radius;
      const glm::dvec3 point = g.dome.eye + (-b + std::sqrt(b * b - c)) * dir;
      std::vector<Sight> sights;
      bool nearAnEdge = false;
      for (std::size_t p = 0; p < g.dome.projectors.size(); ++p) {
        double column = 0, row = 0;
        if (!geometry.project(p, point, column, row)) continue;
        const auto& pr = g.dome.projectors[p];
        const double edge = std::min({column, pr.width - column, row, pr.height - row});
        if (edge > inset) sights.push_back({p, column, row, edge});
        else if (edge > -inset) nearAnEdge = true;
      }
      visit(geometry, point, sights, nearAnEdge);
    }
}

// The dome's geometry test: for every dome point lit by two projectors, each projector's pixel
// there (pinhole), its warp (u, v) and its region camera give one sky direction, within the
// angle one projector pixel spans at that point as seen from the eye.
TEST(DomeGenerator, OverlappingProjectorsShowOneDirection) {
  const Generated& g = generated();
  int pairs = 0;
  double worstPixels = 0.0;
  forEachDomePoint(g, 0.5, [&](const DomeGeometry& geometry, const glm::dvec3& point, const std::vector<Sight>& sights,
                               bool) {
    if (sights.size() < 2) return;
    std::vector<glm::dvec3> shown;
    double pixelAngle = 1e9;
    for (const Sight& s : sights) {
      const ProjectorCalibration& cal = g.calibrations[s.projector];
      const double u = sampleMap(cal.warp, cal.width, cal.height, s.column, s.row, 0);
      const double v = sampleMap(cal.warp, cal.width, cal.height, s.column, s.row, 1);
      ASSERT_TRUE(std::isfinite(u) && std::isfinite(v)) << cal.region << " at " << s.column << "," << s.row;
      shown.push_back(skyig::calibration::directionOfUv(cal.camera, {u, v}));
      // One pixel of this projector here, as seen from the eye.
      const auto a = geometry.trace(s.projector, s.column, s.row), b = geometry.trace(s.projector, s.column + 1.0, s.row);
      pixelAngle = std::min(pixelAngle, std::acos(std::clamp(
                                            glm::dot(geometry.eyeDirection(a.point), geometry.eyeDirection(b.point)), -1.0, 1.0)));
    }
    const glm::dvec3 truth = geometry.eyeDirection(point);
    for (std::size_t i = 0; i < shown.size(); ++i) {
      const double offTruth = std::acos(std::clamp(glm::dot(shown[i], truth), -1.0, 1.0));
      EXPECT_LT(offTruth, pixelAngle) << g.calibrations[sights[i].projector].region;
      for (std::size_t j = i + 1; j < shown.size(); ++j) {
        const double apart = std::acos(std::clamp(glm::dot(shown[i], shown[j]), -1.0, 1.0));
        EXPECT_LT(apart, pixelAngle) << g.calibrations[sights[i].projector].region << " and "
                                     << g.calibrations[sights[j].projector].region;
        worstPixels = std::max(worstPixels, apart / pixelAngle);
        ++pairs;
      }
    }
  });
  // The default dome overlaps: forward neighbours, the chin pair, and forward with chin.
  EXPECT_GT(pairs, 1000);
  RecordProperty("worst_disagreement_in_pixels", std::to_string(worstPixels));
}

// Interpolated as the pass reads them, the alphas of the projectors lighting a point of the
// dome add up to 1 everywhere it is lit, overlaps included.
TEST(DomeGenerator, AlphasSumToOneOverTheLitDome) {
  const Generated& g = generated();
  int lit = 0, overlapped = 0;
  forEachDomePoint(g, 0.5, [&](const DomeGeometry&, const glm::dvec3&, const std::vector<Sight>& sights, bool nearAnEdge) {
    if (!insideTheLitDome(sights) || nearAnEdge) return;
    double sum = 0.0;
    for (const Sight& s : sights) {
      const ProjectorCalibration& cal = g.calibrations[s.projector];
      sum += sampleMap(cal.alpha, cal.width, cal.height, s.column, s.row, 0);
    }
    EXPECT_NEAR(sum, 1.0, 1e-3);
    ++lit;
    if (sights.size() > 1) ++overlapped;
  });
  EXPECT_GT(lit, 10000);
  EXPECT_GT(overlapped, 1000);
}

// With every projector driven at black (l = 0, so it sends l_out = beta), the light at a point
// is each projector's own black b plus the beta it adds: the same wherever one, two or three
// projectors overlap. Without beta it would differ by b per extra projector.
TEST(DomeGenerator, BetaMakesTheBlackFloorUniform) {
  const Generated& g = generated();
  const double b = 1.0 / g.dome.contrast;
  double low = 1e9, high = 0.0;
  int minCount = 99, maxCount = 0;
  forEachDomePoint(g, 2.0, [&](const DomeGeometry&, const glm::dvec3&, const std::vector<Sight>& sights, bool nearAnEdge) {
    if (!insideTheLitDome(sights) || nearAnEdge) return;
    double black = 0.0;
    for (const Sight& s : sights) {
      const ProjectorCalibration& cal = g.calibrations[s.projector];
      const double beta = sampleMap(cal.beta, cal.width, cal.height, s.column, s.row, 0);
      black += b + (1.0 - b) * beta;
    }
    low = std::min(low, black);
    high = std::max(high, black);
    minCount = std::min(minCount, static_cast<int>(sights.size()));
    maxCount = std::max(maxCount, static_cast<int>(sights.size()));
  });
  ASSERT_EQ(minCount, 1);
  ASSERT_EQ(maxCount, g.summary.maxOverlap);
  ASSERT_GE(maxCount, 2);
  // The floor is the deepest overlap's summed black, to within a percent of one projector's.
  EXPECT_NEAR(high, b * maxCount, 0.01 * b);
  EXPECT_NEAR(low, b * maxCount, 0.01 * b);
}

// Each projector's image corners land on the dome along its lens's frustum (as seen from the
// projector), and its whole border lies inside its region camera's image, touching each side
// of it within the margin: the region camera is the footprint's, no more.
TEST(DomeGenerator, AFootprintIsWhereItsFrustumSays) {
  const Generated& g = generated();
  const DomeGeometry geometry(g.dome);
  for (std::size_t p = 0; p < g.dome.projectors.size(); ++p) {
    const auto& pr = g.dome.projectors[p];
    const ProjectorCalibration& cal = g.calibrations[p];
    // Corners, seen from the projector in its own frame.
    const glm::dmat3 eyeToBody =
        glm::inverse(skyig::sky::bodyToEnu({})) * skyig::sky::eyeToEnu({}, pr.orientation);
    for (auto [column, row, h, v] : {std::tuple{0.0, 0.0, -pr.lens.leftDeg, pr.lens.upDeg},
                                     std::tuple{1.0 * pr.width, 1.0 * pr.height, pr.lens.rightDeg, -pr.lens.downDeg}}) {
      const auto hit = geometry.trace(p, column, row);
      ASSERT_TRUE(hit.hit);
      const glm::dvec3 c = glm::transpose(eyeToBody) * (hit.point - pr.position);
      EXPECT_NEAR(std::atan2(c.y, c.x) / kDeg, h, 1e-6) << pr.name;
      EXPECT_NEAR(std::atan2(-c.z, c.x) / kDeg, v, 1e-6) << pr.name;
      EXPECT_NEAR(glm::length(hit.point), g.dome.radius, 1e-9) << pr.name;
    }
    // The border from the eye, in the region camera's image.
    double uMin = 1, uMax = 0, vMin = 1, vMax = 0;
    auto visit = [&](double column, double row) {
      const auto hit = geometry.trace(p, column, row);
      const auto uv = skyig::calibration::uvOfDirection(cal.camera, geometry.eyeDirection(hit.point));
      ASSERT_TRUE(uv && uv->x >= 0.0 && uv->x <= 1.0 && uv->y >= 0.0 && uv->y <= 1.0) << pr.name << " " << column << "," << row;
      const double u = uv->x, v = uv->y;
      uMin = std::min(uMin, u), uMax = std::max(uMax, u), vMin = std::min(vMin, v), vMax = std::max(vMax, v);
    };
    for (int i = 0; i <= pr.width; ++i) visit(i, 0), visit(i, pr.height);
    for (int j = 0; j <= pr.height; ++j) visit(0, j), visit(pr.width, j);
    // The margin is 1 degree of a frustum of some 40 degrees a side: a few percent of the image.
    for (double gap : {uMin, 1.0 - uMax, vMin, 1.0 - vMax}) {
      EXPECT_GT(gap, 0.0) << pr.name;
      EXPECT_LT(gap, 0.03) << pr.name;
    }
    // The warp has a sample for every pixel of a projector inside the dome.
    for (float w : cal.warp.values) ASSERT_TRUE(std::isfinite(w)) << pr.name;
  }
}

// The default dome's overlaps are the helicopter dome's: forward neighbours share 10 to 15
// degrees, as the generator's summary reports them.
TEST(DomeGenerator, ForwardNeighboursOverlapByTenToFifteenDegrees) {
  const Generated& g = generated();
  int forward = 0;
  for (const auto& o : g.summary.overlaps) {
    if ((o.a == 0 && o.b == 1) || (o.a == 1 && o.b == 2)) {
      EXPECT_GE(o.degrees, 10.0);
      EXPECT_LE(o.degrees, 15.0);
      ++forward;
    }
  }
  EXPECT_EQ(forward, 2);
}

TEST(DomeGenerator, AProjectorOutsideTheDomeIsRefusedByName) {
  Dome dome = skyig::calibration::defaultHelicopterDome(160, 100);
  dome.projectors[3].position = {4.0, 0.0, 0.0};
  try {
    skyig::calibration::generateDome(dome);
    FAIL() << "generated a dome with a projector outside it";
  } catch (const skyig::calibration::CalibrationError& e) {
    EXPECT_NE(std::string(e.what()).find("chin-left"), std::string::npos) << e.what();
  }
}

}  // namespace
