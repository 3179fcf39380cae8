#include "sky/shown_layers.h"

#include "physics/stars/star_physics.h"
#include "physics/physics.h"

#include <algorithm>
#include <limits>

namespace skyig::sky {

double displayedCode(double worldCdM2, const eye::ToneCurve& curve, const DisplayParams& display) {
  const double ld = curve.displayLuminance(worldCdM2);
  return 255.0 * shader::displayValue(ld, display.ambientLuminance, display.maxLuminance, display.gamma);
}

namespace {

// Whether `layer` of some cell, times `margin`, moves the code by kShownCodes or more.
template <typename Layer>
bool shownSomewhere(const std::vector<ViewCellLight>& cells, const eye::ToneCurve& curve, const DisplayParams& display,
                    Layer layer, double margin) {
  for (const ViewCellLight& c : cells) {
    const double own = layer(c);
    if (own <= 0.0) continue;
    const double without = double(c.sunlit) + double(c.moonlit) + double(c.night) - own;
    if (displayedCode(without + margin * own, curve, display) - displayedCode(without, curve, display) >= kShownCodes)
      return true;
  }
  return false;
}

}  // namespace

ShownLayers shownLayers(const std::vector<ViewCellLight>& cells, const std::vector<DisplayParams>& displays,
                        const std::vector<std::pair<DisplayParams, eye::ToneCurve>>& curves) {
  ShownLayers shown;
  if (cells.empty() || displays.empty()) return shown;
  for (const DisplayParams& d : displays)
    if (d.toneOperator != ToneOperator::Histogram) return shown;
  shown.sunlitSky = shown.moonlitSky = shown.nightLight = shown.mesopic = false;
  for (const ViewCellLight& c : cells)
    shown.mesopic = shown.mesopic || double(c.sunlit) + double(c.moonlit) + double(c.night) < kPhotopicCdM2 * kPhotopicMargin;
  for (const auto& [display, curve] : curves) {
    shown.sunlitSky = shown.sunlitSky ||
                      shownSomewhere(cells, curve, display, [](const ViewCellLight& c) { return double(c.sunlit); },
                                     kSunlitSkyMargin);
    shown.moonlitSky = shown.moonlitSky ||
                       shownSomewhere(cells, curve, display, [](const ViewCellLight& c) { return double(c.moonlit); },
                                      kMoonlitSkyMargin);
    shown.nightLight = shown.nightLight ||
                       shownSomewhere(cells, curve, display, [](const ViewCellLight& c) { return double(c.night); },
                                      kNightLightMargin);
  }
  return shown;
}

double faintestPointSourceSeenLux(const std::vector<ViewCellLight>& cells) {
  if (cells.empty()) return 0.0;
  double darkest = std::numeric_limits<double>::infinity();
  for (const ViewCellLight& c : cells) darkest = std::min(darkest, double(c.sunlit) + double(c.moonlit) + double(c.night));
  return shader::pointSourceThresholdLux(darkest / kPointSourceMargin);
}

bool pointSourcesSeen(const std::vector<ViewCellLight>& cells, double brightestLux) {
  return cells.empty() || brightestLux > faintestPointSourceSeenLux(cells);
}

}  // namespace skyig::sky
