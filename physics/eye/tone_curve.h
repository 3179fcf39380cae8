#pragma once
// The display mapping of a whole scene, computed once per state on the worker from the sky
// model (never from a channel's pixels, so every channel and node maps alike): Ward Larson,
// Rushmeier & Piatko 1997, "A visibility matching tone reproduction operator for high dynamic
// range scenes" (IEEE TVCG 3(4), section 4-5), histogram adjustment with a ceiling from the
// eye's threshold-versus-intensity function. It shows no contrast the eye could not see in the
// world, and keeps every contrast it could see where the display's range allows; where the
// scene's range fits the display it falls back to Ward's (1994) contrast-based scale factor,
// which maps a just-visible world difference to a just-visible display difference.
//
// How bright the scene is on the display is Tumblin & Rushmeier's (1993) brightness match: the
// curve spans the display only up to the brightness-matched luminance of the scene's brightest
// part, and a scene whose range fits is shown at the brightness-matched luminance of its own
// level with its contrasts kept (slope 1 in log). A night therefore looks dark, a day bright,
// and neither gains contrast it does not have.
#include <array>
#include <vector>

namespace skyig::sky::eye {

// Luminances seen over the whole view sphere, weighted by solid angle (steradians).
struct LuminanceHistogram {
  static constexpr int kBins = 100;
  double minLog10 = -6.0;  // log10 cd/m^2 of the lower edge of bin 0
  double maxLog10 = 10.0;  // upper edge of the last bin
  std::array<double, kBins> weight{};
  // Luminances above this (log10 cd/m^2) are highlights, the sun's and moon's discs: the curve
  // is equalised and placed below it and continues above it with slope 1, so a disc is shown
  // brighter than anything around it (white, where it exceeds the display) and an extended
  // bright area (a sunlit cloud deck or terrain seen from 12 km) is not pushed to white.
  double highlightLog10 = 1e300;

  // Adds `solidAngle` sr of luminance `cdM2` (ignored when not positive and finite).
  void add(double cdM2, double solidAngle);
  double total() const;
  // The solid-angle weighted log-mean luminance (cd/m^2): the scene's steady adaptation level.
  double logMean() const;
  // The log10 luminance below which `fraction` of the weight lies (a bin's upper edge).
  double percentileLog10(double fraction) const;
};

// How far below the display's white (log10) the brightest extended part of a scene is shown:
// 0.1, i.e. 80% of white, leaving the top for the sun's and moon's discs and their glare. Above
// ~80% of white a saturated colour cannot keep its hue (its brightest channel clips) and turns
// to white along it (physics/eye/tone_reproduction.glsl, compressToDisplay).
inline constexpr double kHighlightHeadroomLog10 = 0.1;

// The share of the view above a fitting scene's knee: its brightest tenth (by solid angle), the
// part whose contrasts roll off when the scene's matched level leaves it no room under the top.
inline constexpr double kKneeShare = 0.1;

// The least room a fitting scene keeps between its knee and the top of its extended part
// (log10: 1.6x), where its matched level would put the knee higher still.
inline constexpr double kShoulderHeadroomLog10 = 0.2;

// The shoulder of a fitting scene's curve above its knee (log10 luminance): `above` the knee, the
// brightest extended part `range` above it, shown at most `headroom` above the knee's display
// luminance. Slope 1 where the range fits the headroom; else a rational roll-off from slope 1 at
// the knee to the top at `range`.
double shoulder(double above, double range, double headroom);

// The range the display can show: black (its ambient) to white, cd/m^2, and the luminance its
// viewer is adapted to (Tumblin & Rushmeier's L_a(d)).
struct DisplayRange {
  double minCdM2 = 0.1;
  double maxCdM2 = 100.0;
  double adaptationCdM2 = 10.0;
};

// World log10 luminance -> display log10 luminance, sampled at kPoints evenly spaced world
// levels from minLog10 to maxLog10 (linear between samples, clamped outside).
struct ToneCurve {
  static constexpr int kPoints = 64;
  double minLog10 = -6.0;
  double maxLog10 = 10.0;
  std::array<float, kPoints> displayLog10{};
  bool linear = false;  // Ward's scale factor was used (the scene's range fits the display)

  double displayLuminance(double worldCdM2) const;
};

// Which ceiling bounds the histogram's slopes (WLRP97 section 4):
//   Linear: dLd/dLw <= Ld/Lw, no contrast is shown larger than it is in the world (section 4.1);
//   Threshold: the display slope is further bounded by the ratio of the eye's thresholds at the
//     display and world luminances (eq. 10), with the threshold-versus-intensity function of
//     physics/eye/threshold.glsl. That function is measured for small test spots; large, faint
//     night features (the Milky Way, a moonlit horizon) that a dark-adapted eye does see fall
//     below it and vanish, so it is not the default (docs/tone-reproduction.md).
enum class Ceiling { Linear, Threshold };

// The histogram-adjusted curve for `histogram` on `display`; `adaptationGain` >= 0 scales the
// display luminance for an eye not (yet) adapted to the scene (1 when adapted; see
// physics/eye/adaptation.h). Throws std::invalid_argument for an empty histogram or a bad range.
ToneCurve histogramAdjustment(const LuminanceHistogram& histogram, const DisplayRange& display,
                              double adaptationGain = 1.0, Ceiling ceiling = Ceiling::Linear);

// Ward 1994 ("A contrast-based scalefactor for luminance display", Graphics Gems IV): the
// display luminance per world luminance that maps threshold to threshold between a world
// adapted to worldAdaptation and a display viewer adapted to displayAdaptation (cd/m^2).
double wardScaleFactor(double worldAdaptation, double displayAdaptation);

}  // namespace skyig::sky::eye
