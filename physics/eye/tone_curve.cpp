#include "physics/eye/tone_curve.h"

#include "physics/eye/eye_physics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace skyig::sky::eye {

namespace {

constexpr int kBins = LuminanceHistogram::kBins;

double binWidth(const LuminanceHistogram& h) { return (h.maxLog10 - h.minLog10) / kBins; }
double binCentre(const LuminanceHistogram& h, int i) { return h.minLog10 + (i + 0.5) * binWidth(h); }

}  // namespace

void LuminanceHistogram::add(double cdM2, double solidAngle) {
  if (!(cdM2 > 0.0) || !std::isfinite(cdM2) || !(solidAngle > 0.0)) return;
  const double b = std::log10(cdM2);
  const int i = std::clamp(static_cast<int>(std::floor((b - minLog10) / (maxLog10 - minLog10) * kBins)), 0, kBins - 1);
  weight[static_cast<std::size_t>(i)] += solidAngle;
}

double LuminanceHistogram::total() const {
  double t = 0.0;
  for (double w : weight) t += w;
  return t;
}

double LuminanceHistogram::percentileLog10(double fraction) const {
  const double wanted = fraction * total();
  double run = 0.0;
  for (int i = 0; i < kBins; ++i) {
    run += weight[static_cast<std::size_t>(i)];
    if (run >= wanted && run > 0.0) return minLog10 + (i + 1) * (maxLog10 - minLog10) / kBins;
  }
  return maxLog10;
}

double LuminanceHistogram::logMean() const {
  double sum = 0.0, t = 0.0;
  for (int i = 0; i < kBins; ++i) {
    sum += weight[static_cast<std::size_t>(i)] * binCentre(*this, i);
    t += weight[static_cast<std::size_t>(i)];
  }
  return t > 0.0 ? std::pow(10.0, sum / t) : 0.0;
}

double ToneCurve::displayLuminance(double worldCdM2) const {
  // A NaN luminance is shown black, not cast to an index (the cast of NaN is undefined).
  const double x = std::isnan(worldCdM2) ? 0.0 : shader::toneCurvePosition(worldCdM2, glm::dvec2(minLog10, maxLog10), double(kPoints));
  const int i = std::min(static_cast<int>(x), kPoints - 2);
  return shader::toneCurveLuminance(double(displayLog10[static_cast<std::size_t>(i)]),
                                    double(displayLog10[static_cast<std::size_t>(i + 1)]), x - i);
}

double shoulder(double above, double range, double headroom) {
  // Below the knee, and wherever the brightest extended part fits under the top: slope 1.
  if (above <= 0.0 || range <= 0.0 || range <= headroom) return above;
  // Above it the rational roll-off y = u / (1 + k u), k = 1/H - 1/U: slope 1 at the knee (no
  // kink in the curve), y(U) = H (the brightest extended part at the top, never past it),
  // monotonic, and the slope (H/U)^2 at the top.
  const double u = std::min(above, range);
  return u / (1.0 + u * (1.0 / headroom - 1.0 / range));
}

double wardScaleFactor(double worldAdaptation, double displayAdaptation) {
  // Ward 1994, eq. 5 (Blackwell's threshold fit, luminances in cd/m^2).
  return std::pow((1.219 + std::pow(displayAdaptation, 0.4)) / (1.219 + std::pow(std::max(worldAdaptation, 1e-12), 0.4)), 2.5);
}

ToneCurve histogramAdjustment(const LuminanceHistogram& histogram, const DisplayRange& display, double adaptationGain,
                              Ceiling ceilingKind) {
  if (!(display.minCdM2 > 0.0) || !(display.maxCdM2 > display.minCdM2) || !std::isfinite(display.maxCdM2))
    throw std::invalid_argument("display range " + std::to_string(display.minCdM2) + ".." +
                                std::to_string(display.maxCdM2) + " cd/m^2 is not a range of positive luminances");
  if (!(adaptationGain >= 0.0) || !std::isfinite(adaptationGain))
    throw std::invalid_argument("adaptation gain " + std::to_string(adaptationGain) + " is not a finite non-negative number");
  const double total0 = histogram.total();
  if (!(total0 > 0.0)) throw std::invalid_argument("tone curve of an empty luminance histogram");

  // The world's range: the first to the last occupied bin.
  int lo = 0, hi = kBins - 1;
  while (lo < hi && histogram.weight[static_cast<std::size_t>(lo)] <= 0.0) ++lo;
  while (hi > lo && histogram.weight[static_cast<std::size_t>(hi)] <= 0.0) --hi;
  const double dB = binWidth(histogram);
  const double worldMin = histogram.minLog10 + lo * dB, worldTop = histogram.minLog10 + (hi + 1) * dB;
  // The extended part of the scene: bins up to the highlight level.
  if (histogram.highlightLog10 < worldTop) {
    const int h = static_cast<int>(std::floor((histogram.highlightLog10 - histogram.minLog10) / dB));
    hi = std::clamp(h, lo, hi);
  }
  const double worldMax = histogram.minLog10 + (hi + 1) * dB;
  // Brightness matching (Tumblin & Rushmeier 1993) sets where the scene sits on the display:
  // the top of the curve at the matched luminance of the scene's brightest part, and (when the
  // scene fits) its level at the matched luminance of that level.
  const double level = histogram.logMean();
  auto matched = [&](double worldLog10) {
    return std::log10(std::clamp(shader::tumblinRushmeierDisplayLuminance(std::pow(10.0, worldLog10), level,
                                                                          display.adaptationCdM2),
                                 display.minCdM2, display.maxCdM2));
  };
  const double dMin = std::log10(display.minCdM2);
  // The extended scene tops out a little below the display's white, so that only the discs and
  // their glare reach it and an extended bright area keeps its hue (kHighlightHeadroomLog10).
  const double dTop = std::log10(display.maxCdM2) - kHighlightHeadroomLog10;
  const double dMax = std::max(std::min(matched(worldMax), dTop), dMin + 0.5), dRange = dMax - dMin;

  ToneCurve curve;
  curve.minLog10 = worldMin;
  curve.maxLog10 = std::max(worldTop, worldMax);
  std::array<double, kBins> f = histogram.weight;
  // The display brightness of each bin's centre under the cumulative distribution of f
  // (WLRP97 eq. 4): B_d = log Ldmin + (log Ldmax - log Ldmin) P(B_w).
  auto mapping = [&](const std::array<double, kBins>& h, std::array<double, kBins + 1>& edges) {
    double t = 0.0;
    for (int i = lo; i <= hi; ++i) t += h[static_cast<std::size_t>(i)];
    double run = 0.0;
    edges[static_cast<std::size_t>(lo)] = dMin;
    for (int i = lo; i <= hi; ++i) {
      run += h[static_cast<std::size_t>(i)];
      edges[static_cast<std::size_t>(i + 1)] = dMin + dRange * (t > 0.0 ? run / t : 0.0);
    }
    return t;
  };
  std::array<double, kBins + 1> edges{};
  // Histogram adjustment with a ceiling (WLRP97 eq. 9-10): no bin may give its luminances a
  // larger display slope than the ceiling allows,
  //   f(b) <= [dLt(Ld) / dLt(Lw)] T db Lw / ((log Ldmax - log Ldmin) Ld),
  // where the ratio of thresholds is Ld / Lw for the linear ceiling (the bound is then
  // T db / (log Ldmax - log Ldmin), eq. 9).
  constexpr double kTolerance = 0.025;  // WLRP97: stop when less than 2.5% is trimmed
  double t = mapping(f, edges);
  for (int iteration = 0; iteration < 50 && t > kTolerance * total0; ++iteration) {
    double trimmed = 0.0;
    for (int i = lo; i <= hi; ++i) {
      const double bw = binCentre(histogram, i);
      const double bd = 0.5 * (edges[static_cast<std::size_t>(i)] + edges[static_cast<std::size_t>(i + 1)]);
      const double thresholdRatio =
          ceilingKind == Ceiling::Threshold
              ? std::pow(10.0, shader::log10ThresholdLuminance(bd) - shader::log10ThresholdLuminance(bw))
              : std::pow(10.0, bd - bw);  // the linear ceiling: dLd/dLw <= Ld/Lw
      const double ceiling = thresholdRatio * t * dB * std::pow(10.0, bw - bd) / dRange;
      double& fi = f[static_cast<std::size_t>(i)];
      if (fi > ceiling) {
        trimmed += fi - ceiling;
        fi = ceiling;
      }
    }
    t = mapping(f, edges);
    if (trimmed < kTolerance * t) break;
  }
  const double gain = std::log10(std::max(adaptationGain, 1e-30));
  if (t > kTolerance * total0) {
    for (int k = 0; k < ToneCurve::kPoints; ++k) {
      const double bw = worldMin + (curve.maxLog10 - worldMin) * k / (ToneCurve::kPoints - 1);
      const double x = std::clamp((bw - histogram.minLog10) / dB, double(lo), double(hi + 1));
      const int i = std::min(static_cast<int>(x), hi);
      const double fr = x - i;
      const double bd = (1.0 - fr) * edges[static_cast<std::size_t>(i)] + fr * edges[static_cast<std::size_t>(i + 1)] +
                        std::max(bw - worldMax, 0.0);  // highlights: slope 1 above the extended scene
      curve.displayLog10[static_cast<std::size_t>(k)] = static_cast<float>(std::min(bd + gain, std::log10(display.maxCdM2) + 3.0));
    }
    return curve;
  }
  // The ceiling left (almost) nothing to equalise: the scene's range fits the display. Keep its
  // contrasts (slope 1 in log luminance) about its level, placed at the level's matched
  // luminance; raised where its darkest part would fall below the display's black, as far as
  // its brightest extended part stays under the top. Where the matched level leaves the
  // brightest part no room, the contrasts are kept up to the knee, the brightest tenth of the
  // view (kKneeShare), and what lies above the knee rolls off into the room under the top
  // (shoulder()); the level is lowered only as far as the knee needs. A bright day's sky around
  // the sun is 10-20 times its level, a tenth of the view or less: when the whole frame was
  // lowered until it fitted, a hazy afternoon showed as dusk. A night sky's faint features (the
  // Milky Way at the zenith) lie below its knee and keep their contrast.
  curve.linear = true;
  const double levelLog10 = std::log10(level);
  // Not std::clamp: a level above the extended scene's top (a scene of one bin and a disc) would
  // make its bounds cross, which is undefined; the knee is then the level and nothing rolls off.
  const double kneeLog10 = std::max(levelLog10, std::min(histogram.percentileLog10(1.0 - kKneeShare), worldMax));
  const double matchedAnchor = matched(levelLog10) - levelLog10;
  const double lowest = dMin - worldMin, highest = dMax - worldMax;
  const double kneeHighest = dMax - kShoulderHeadroomLog10 - kneeLog10;  // the knee, with room above it
  const double anchor = std::max(std::min(matchedAnchor, std::max(highest, kneeHighest)), std::min(lowest, highest));
  const double dKnee = kneeLog10 + anchor;
  for (int k = 0; k < ToneCurve::kPoints; ++k) {
    const double bw = worldMin + (curve.maxLog10 - worldMin) * k / (ToneCurve::kPoints - 1);
    const double bd = dKnee + shoulder(bw - kneeLog10, worldMax - kneeLog10, dMax - dKnee) +
                      std::max(bw - worldMax, 0.0);  // highlights: slope 1 above the extended scene
    curve.displayLog10[static_cast<std::size_t>(k)] = static_cast<float>(std::min(bd + gain, std::log10(display.maxCdM2) + 3.0));
  }
  return curve;
}

}  // namespace skyig::sky::eye
