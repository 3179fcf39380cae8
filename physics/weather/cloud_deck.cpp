#include "physics/weather/cloud_deck.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "physics/weather/cloud_layer.h"

namespace skyig::weather {

namespace {

using sky::CloudType;

// A type's content and particles, and its field's look. Extinction in the geometric-optics limit
// (particles far larger than the wavelength, extinction efficiency 2): beta = 3 W / (2 rho r_e)
// for a water (or ice) content W and effective radius r_e (Stephens 1978, "Radiation profiles
// in extended water clouds. II", J. Atmos. Sci. 35, eq. 1; Hansen & Travis 1974). Contents and
// radii are mid-range values of aircraft measurements (water clouds: Miles, Verlinde &
// Clothiaux 2000, J. Atmos. Sci. 57, 0.1-0.6 g/m^3 and 5-10 um in low stratiform cloud; cumulus
// denser; cirrus: Heymsfield & McFarquhar 2002, 0.001-0.1 g/m^3, tens of um). The asymmetry is
// that of droplets (0.85, Hansen & Travis) or of ice crystals (0.75, Macke et al. 1996).
// The field: a cell of the lattice is about one cloud (cumulus ~1 km across), its edge soft or
// crisp, its streaks stretched along the wind (cirrus).
struct TypeLook {
  double contentGPerM3, radiusUm, densityGPerM3, asymmetry;
  double cellM, softness, stretch;
};
constexpr double kWater = 1.0e6, kIce = 0.917e6;
constexpr std::array<TypeLook, 10> kTypes{{
    {0.30, 8.0, kWater, 0.85, 1500.0, 0.06, 1.0},   // altocumulus: a sheet of cloudlets
    {0.25, 8.0, kWater, 0.85, 4000.0, 0.10, 1.0},   // altostratus
    {0.02, 25.0, kIce, 0.75, 1200.0, 0.08, 2.0},    // cirrocumulus
    {0.03, 30.0, kIce, 0.75, 6000.0, 0.15, 3.0},    // cirrostratus
    {0.02, 30.0, kIce, 0.75, 4000.0, 0.12, 4.0},    // cirrus
    {1.00, 12.0, kWater, 0.85, 5000.0, 0.04, 1.0},  // cumulonimbus
    {0.60, 9.0, kWater, 0.85, 1000.0, 0.04, 1.0},   // cumulus
    {0.60, 10.0, kWater, 0.85, 5000.0, 0.10, 1.0},  // nimbostratus
    {0.30, 9.0, kWater, 0.85, 2000.0, 0.06, 1.0},   // stratocumulus
    {0.45, 8.0, kWater, 0.85, 3000.0, 0.08, 1.0},   // stratus
}};
const TypeLook& lookOf(CloudType t) { return kTypes[static_cast<std::size_t>(t) - 1]; }

// The field's values over one period, sorted: its distribution, for the coverage's quantile.
const std::vector<double>& sortedField() {
  static const std::vector<double> values = [] {
    constexpr int kPerSide = 384;  // 1.5 samples a cell over the 256-cell period
    std::vector<double> v;
    v.reserve(kPerSide * kPerSide);
    const double step = static_cast<double>(shader::kCloudPeriodCells) / kPerSide;
    for (int y = 0; y < kPerSide; ++y)
      for (int x = 0; x < kPerSide; ++x) v.push_back(shader::cloudField(glm::dvec2((x + 0.5) * step, (y + 0.5) * step), 0));
    std::sort(v.begin(), v.end());
    return v;
  }();
  return values;
}

// Where smoothstep(-1, 1, x) passes 1 - 1/e: 3 s^2 - 2 s^3 = 0.632 at s = (x + 1) / 2 = 0.588.
constexpr double kThickAt = 2.0 * 0.5881 - 1.0;

}  // namespace

double severityContentFactor(int severity) { return std::pow(6.0, (std::clamp(severity, 0, 5) - 2) / 5.0); }

CloudOptics cloudOptics(const sky::CloudLayer& layer) {
  const TypeLook& t = lookOf(layer.type);
  CloudOptics o;
  o.asymmetry = t.asymmetry;
  const double content = t.contentGPerM3 * severityContentFactor(layer.severity);
  o.extinctionPerM = layer.visibilityM > 0.0 ? sky::kKoschmiederConstant / layer.visibilityM
                                             : 3.0 * content / (2.0 * t.densityGPerM3 * t.radiusUm * 1e-6);
  return o;
}

sky::FogSpec deckSpec(const sky::CloudLayer& layer) {
  const CloudOptics o = cloudOptics(layer);
  sky::FogSpec s;
  s.bottomM = layer.baseM;
  s.topM = layer.baseM + layer.thicknessM;
  s.visibilityKm = sky::kKoschmiederConstant / o.extinctionPerM / 1000.0;
  s.asymmetry = o.asymmetry;
  s.transitionM = layer.topTransitionM;                       // the top's band
  s.bottomTransitionM = std::min(layer.transitionM, layer.baseM);  // the base's, down to the ground at most
  return s;
}

FogLayer makeCloudDeck(const sky::CloudLayer& layer, double planetRadiusM, double groundAlbedo,
                       const glm::dvec3& topIrradiance) {
  validate(layer);
  FogLayer f = makeFogLayer(deckSpec(layer), planetRadiusM, groundAlbedo, topIrradiance);
  f.gap = 1.0 - layer.coveragePct / 100.0;
  f.limb_darkening = kDeckLimbDarkening;
  return f;
}

double cloudThreshold(double coverage, double softness) {
  const std::vector<double>& v = sortedField();
  const double q = std::clamp(1.0 - coverage, 0.0, 1.0) * static_cast<double>(v.size() - 1);
  const std::size_t i = static_cast<std::size_t>(q);
  const double value = i + 1 < v.size() ? v[i] + (q - static_cast<double>(i)) * (v[i + 1] - v[i]) : v.back();
  return value - kThickAt * softness;
}

glm::dvec2 cloudGroundPosition(double latitudeDeg, double longitudeDeg, double planetRadiusM) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  return {planetRadiusM * longitudeDeg * kDeg * std::cos(latitudeDeg * kDeg), planetRadiusM * latitudeDeg * kDeg};
}

CloudCover cloudCoverOf(const sky::CloudLayer& layer, int index, double eastM, double northM, double timeS) {
  CloudCover c;
  if (!layer.enabled) return c;
  const TypeLook& t = lookOf(layer.type);
  c.broken = layer.coveragePct < 100.0;
  c.midHeightM = layer.baseM + 0.5 * layer.thicknessM;
  c.cellM = t.cellM;
  c.softness = t.softness;
  c.stretch = t.stretch;
  c.coverage = layer.coveragePct / 100.0;
  c.threshold = cloudThreshold(c.coverage, t.softness);
  c.seed = 101 * (index + 1) + static_cast<int>(layer.type);
  // The wind blows from windFromDeg: the clouds go the other way, speed * time metres by now.
  const double to = (layer.windFromDeg + 180.0) * std::numbers::pi / 180.0;
  if (layer.windSpeedMps > 0.0) c.along = {std::sin(to), std::cos(to)};
  const glm::dvec2 moved = layer.windSpeedMps * timeS * glm::dvec2(std::sin(to), std::cos(to));
  // The field's own frame: along the wind, and across it `stretch` times finer.
  const glm::dvec2 eye = glm::dvec2(eastM, northM) - moved;
  const glm::dvec2 across(c.along.y, -c.along.x);
  const glm::dvec2 cells(glm::dot(eye, c.along) / t.cellM, glm::dot(eye, across) * t.stretch / t.cellM);
  const double period = shader::kCloudPeriodCells;
  c.origin = {cells.x - period * std::floor(cells.x / period), cells.y - period * std::floor(cells.y / period)};
  return c;
}

double cloudShareAt(const CloudCover& cover, const glm::dvec2& offsetM) {
  if (!cover.broken) return 1.0;
  const glm::dvec2 across(cover.along.y, -cover.along.x);
  const glm::dvec2 p = cover.origin + glm::dvec2(glm::dot(offsetM, cover.along) / cover.cellM,
                                                 glm::dot(offsetM, across) * cover.stretch / cover.cellM);
  return shader::cloudMask(p, cover.seed, cover.threshold, cover.softness);
}

}  // namespace skyig::weather
