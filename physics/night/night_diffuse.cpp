#include "physics/night/night_diffuse.h"

#include "physics/spectrum/spectral_data.h"
#include "physics/spectrum/spectrum.h"
#include "physics/common/hemisphere_grid.h"
#include "physics/night/diffuse_physics.h"
#include "physics/night/zodiacal_light.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace skyig::sky::night {

const glm::dvec3& airglowRec709() {
  static const glm::dvec3 colour = [] {
    auto unitY = [](const glm::dvec3& xyz) { return xyz / xyz.y; };
    glm::dvec3 continuum(0.0);
    for (double w = 400.0; w <= 700.0; w += 1.0) continuum += atmosphere::cie1931ColourMatching(w);
    const glm::dvec3 xyz = kAirglowGreenLineShare * unitY(atmosphere::cie1931ColourMatching(557.7)) +
                           kAirglowSodiumShare * unitY(atmosphere::cie1931ColourMatching(589.3)) +
                           (1.0 - kAirglowGreenLineShare - kAirglowSodiumShare) * unitY(continuum);
    const glm::dvec3 rgb = glm::max(atmosphere::xyzToRec709(xyz), glm::dvec3(0.0));
    return rgb / (0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b);
  }();
  return colour;
}

NightDiffuseSky makeNightDiffuseSky(const ephemeris::SkyEphemeris& ephemeris,
                                    std::shared_ptr<const atmosphere::ExtinctionProfile> extinction, bool withMilkyWay) {
  NightDiffuseSky sky;
  const ephemeris::Mat3& m = ephemeris.j2000ToEnu;  // row-major, ENU = M J2000
  // GLM is column-major: enuToJ2000 = M^T, so its column j is M's row j.
  for (int j = 0; j < 3; ++j) sky.enuToJ2000[j] = glm::dvec3(m.m[3 * j], m.m[3 * j + 1], m.m[3 * j + 2]);
  const ephemeris::Vec3& s = ephemeris.sun.enu;
  sky.sunJ2000 = glm::normalize(sky.enuToJ2000 * glm::dvec3(s.x, s.y, s.z));
  sky.airglowZenith = shader::s10ToCdM2(kAirglowZenithS10) * airglowRec709();
  sky.extinction = std::move(extinction);
  if (withMilkyWay) sky.milkyWay = MilkyWayMap::standard();
  return sky;
}

glm::dvec3 nightDiffuseRadianceWithoutMap(const NightDiffuseSky& sky, const glm::dvec3& viewEnu) {
  const glm::dvec3 floor = shader::s10ToCdM2(kPoleS10) * glm::dvec3(1.0);
  return nightDiffuseRadiance(sky, viewEnu).total() + nightExtinction(sky, viewEnu) * floor;
}

glm::dvec3 nightDiffuseIlluminance(const ephemeris::SkyEphemeris& ephemeris,
                                   std::shared_ptr<const atmosphere::ExtinctionProfile> extinction) {
  constexpr int kMu = 8, kPhi = 16;  // each direction stands for 2 pi / (kMu kPhi) sr
  const NightDiffuseSky sky = makeNightDiffuseSky(ephemeris, std::move(extinction), false);
  glm::dvec3 sum(0.0);
  forEachHemisphereDirection(kMu, kPhi, [&](const glm::dvec3& v) { sum += nightDiffuseRadianceWithoutMap(sky, v) * v.z; });
  return sum * (2.0 * std::numbers::pi / (kMu * kPhi));
}

glm::dvec3 nightExtinction(const NightDiffuseSky& sky, const glm::dvec3& viewEnu) {
  const glm::dvec3 v = glm::normalize(viewEnu);
  if (!sky.extinction) return v.z >= 0.0 ? glm::dvec3(1.0) : glm::dvec3(0.0);
  // The profile's Rec.709 factors dip a little below zero in blue at the horizon (a sunlike
  // spectrum's red end left over): no light is negative.
  return glm::max(sky.extinction->rec709(std::asin(std::clamp(v.z, -1.0, 1.0))), glm::dvec3(0.0));
}

NightDiffuseRadiance nightDiffuseRadiance(const NightDiffuseSky& sky, const glm::dvec3& viewEnu) {
  const double n = glm::length(viewEnu);
  if (!std::isfinite(n) || n == 0.0)
    throw std::invalid_argument("night sky: view direction (" + std::to_string(viewEnu.x) + ", " +
                                std::to_string(viewEnu.y) + ", " + std::to_string(viewEnu.z) + ") is zero or not finite");
  const glm::dvec3 v = viewEnu / n;
  const glm::dvec3 t = nightExtinction(sky, v);
  const glm::dvec3 j2000 = sky.enuToJ2000 * v;
  NightDiffuseRadiance r;
  if (sky.milkyWay) r.milkyWay = t * shader::kS10CdM2 * sky.milkyWay->s10(j2000);
  r.zodiacal = t * zodiacalRadiance(j2000, sky.sunJ2000);
  r.airglow = t * shader::airglowRadiance(sky.airglowZenith, v.z);
  return r;
}

}  // namespace skyig::sky::night
