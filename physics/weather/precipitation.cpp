#include "physics/weather/precipitation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "physics/weather/fog_layer.h"

namespace skyig::weather {

namespace {

constexpr double kKoschmieder = sky::kKoschmiederConstant;
constexpr double kPi = 3.14159265358979323846;

struct Optics {
  double asymmetry;
  std::array<double, 3> albedo;  // Rec.709 R, G, B
};

// Water and ice absorb nothing over a drop's width in the visible. Asymmetry: drops and ice
// spheres far larger than the wavelength, 0.87 (geometric optics of water spheres, Hansen &
// Travis 1974, "Light scattering in planetary atmospheres", Space Sci. Rev. 16, 527-610); snow
// crystals 0.75 (Macke, Mueller & Raschke 1996, "Single scattering properties of atmospheric ice
// crystals", J. Atmos. Sci. 53, 2813-2825). Desert dust: Dubovik et al. 2002, "Variability of
// absorption and optical properties of key aerosol types observed in worldwide locations",
// J. Atmos. Sci. 59, 590-608, table 1 (Cape Verde): albedo 0.93 at 440 nm and 0.98 at 670 nm,
// taken linearly at the Rec.709 primaries' dominant wavelengths (612, 549, 465 nm); g 0.73. No
// measured optics of blowing sand were at hand: sand takes dust's.
constexpr Optics kWater{0.87, {1.0, 1.0, 1.0}};
constexpr Optics kSnow{0.75, {1.0, 1.0, 1.0}};
constexpr Optics kDust{0.73, {0.967, 0.954, 0.935}};

const Optics& optics(Precipitation kind) {
  switch (kind) {
    case Precipitation::snow: return kSnow;
    case Precipitation::sand:
    case Precipitation::dust: return kDust;
    default: return kWater;
  }
}

constexpr std::array<std::string_view, kPrecipitationKinds> kNames{"rain", "snow", "sleet", "hail", "sand", "dust"};

int clampedSeverity(int severity) { return std::clamp(severity, 0, 5); }

}  // namespace

std::string_view toString(Precipitation kind) { return kNames[static_cast<std::size_t>(kind)]; }

std::optional<Precipitation> parsePrecipitation(std::string_view text) {
  for (std::size_t i = 0; i < kNames.size(); ++i)
    if (kNames[i] == text) return static_cast<Precipitation>(i);
  return std::nullopt;
}

std::optional<Precipitation> precipitationOfLayer(std::uint8_t layerId) {
  if (layerId < kFirstPrecipitationLayerId || layerId >= kFirstPrecipitationLayerId + kPrecipitationKinds)
    return std::nullopt;
  return static_cast<Precipitation>(layerId - kFirstPrecipitationLayerId);
}

double rainRateMmPerH(int severity) {
  // WMO's rain intensities: light below 2.5 mm/h, moderate to 10, heavy to 50, violent beyond.
  constexpr std::array<double, 6> kRate{1.0, 2.5, 5.0, 10.0, 25.0, 50.0};
  return kRate[static_cast<std::size_t>(clampedSeverity(severity))];
}

double rainVisibilityKm(double rateMmPerH) {
  if (!(rateMmPerH > 0.0)) throw std::invalid_argument("rain rate " + std::to_string(rateMmPerH) + " mm/h: expected above 0");
  const double n0 = 8000.0;                                  // m^-3 mm^-1
  const double lambda = 4.1 * std::pow(rateMmPerH, -0.21);   // mm^-1
  const double sigma = kPi * n0 / (lambda * lambda * lambda) * 1e-6;  // m^-1
  return kKoschmieder / sigma / 1000.0;
}

double visibilityForSeverityKm(Precipitation kind, int severity) {
  const std::size_t s = static_cast<std::size_t>(clampedSeverity(severity));
  switch (kind) {
    case Precipitation::snow: {
      // US Federal Meteorological Handbook No. 1, intensity of snow by visibility: light above
      // 1/2 statute mile (0.8 km), moderate to 1/4 mile (0.4 km), heavy at or below it.
      constexpr std::array<double, 6> kSnowKm{2.0, 1.2, 0.8, 0.6, 0.4, 0.2};
      return kSnowKm[s];
    }
    case Precipitation::sand:
    case Precipitation::dust: {
      // WMO: dust haze and blowing dust above 1 km, a dust storm below 1 km, a severe one below 200 m.
      constexpr std::array<double, 6> kDustKm{5.0, 2.0, 1.0, 0.5, 0.2, 0.1};
      return kDustKm[s];
    }
    default:
      // Rain, and sleet and hail as rain of the same rate: compact particles falling as fast.
      return rainVisibilityKm(rainRateMmPerH(severity));
  }
}

sky::FogSpec precipitationLayer(Precipitation kind, double bottomM, double topM, double visibilityKm, int severity,
                                double coverage) {
  if (!(coverage > 0.0)) return {};
  const double inside = visibilityKm > 0.0 ? visibilityKm : visibilityForSeverityKm(kind, severity);
  const Optics& o = optics(kind);
  sky::FogSpec out{bottomM, topM, inside / std::min(coverage, 1.0), o.asymmetry, o.albedo};
  validate(out);
  return out;
}

sky::FogSpec precipitationLayer(const PrecipitationSettings& s) {
  if (!s.kind) return {};
  return precipitationLayer(*s.kind, 0.0, s.topM, s.visibilityKm, s.severity, s.coveragePct / 100.0);
}

sky::FogSpec combinedLayers(std::span<const sky::FogSpec> layers) {
  double depth = 0.0, scattered = 0.0, g = 0.0, bottom = 0.0, top = 0.0;
  std::array<double, 3> albedo{0.0, 0.0, 0.0};
  bool any = false;
  for (const sky::FogSpec& l : layers) {
    if (l.visibilityKm == 0.0) continue;
    const double tau = kKoschmieder / (l.visibilityKm * 1000.0) * (l.topM - l.bottomM);
    depth += tau;
    scattered += tau * l.albedo[1];
    g += tau * l.albedo[1] * l.asymmetry;
    for (std::size_t c = 0; c < 3; ++c) albedo[c] += tau * l.albedo[c];
    bottom = any ? std::min(bottom, l.bottomM) : l.bottomM;
    top = any ? std::max(top, l.topM) : l.topM;
    any = true;
  }
  if (!any || !(depth > 0.0)) return {};
  for (double& a : albedo) a /= depth;
  return {bottom, top, kKoschmieder / (depth / (top - bottom)) / 1000.0, g / scattered, albedo};
}

}  // namespace skyig::weather
