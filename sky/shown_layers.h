#pragma once
// Which of a state's faint layers can change what its displays show, decided once per state on
// the worker from the view sphere's light by source (sky/view_sphere.h) and the displays' tone
// curves (physics/eye/tone_curve.h): the moonlit sky in daylight, or the night's own light
// (airglow, zodiacal light, the Milky Way, their light on the terrain) at dusk, adds far less
// than the eye can see and changes no display code. The renderer then neither compiles the
// moonlit sky into its sky pass nor draws the diffuse night pass: every pixel pays only for
// what it shows. A layer is shown when, in some cell of the view sphere on some display, it
// moves the displayed value by kShownCodes of an 8-bit code or more with its light multiplied
// by a margin: the cells are ~0.4 sr wide and their mean hides the moon's aureole (margin 10)
// and the Milky Way's bright clouds, which the cells leave out, and the display maps the mesopic
// rather than the photopic luminance (margin 8 for the night's light).
// The displayed stars and planets are left out where even the brightest of them cannot pass the
// eye's point-source threshold against the darkest of the view (pointSourcesSeen): in practice
// rarely by day, since Venus or Jupiter is usually up and can be seen in daylight, but whenever
// the sky is too bright for them. When it runs, it draws only the sources above the same
// threshold (pointSourceFloorLux): by day Venus and Jupiter, not the 4600 stars above the
// horizon, each of which would take the pass's per-star test (against the sky at its own pixel,
// which decides which of the rest are drawn).
// The sun's own sky and ground are left out the same way once night has fallen: with the sun
// far below the horizon its twilight is fainter than the night's own light (astronomical
// twilight ends at -18 degrees by that definition), and a moonlit or moonless night then pays
// for one sky lookup per pixel, or none, instead of two or one. Margin 10 as for the moon: the
// twilight's arch is brightest at the horizon below the sun, a few degrees under the centre of
// the lowest cells.
#include "sky/channel.h"
#include "physics/eye/tone_curve.h"
#include "sky/view_sphere.h"

#include <utility>
#include <vector>

namespace skyig::sky {

inline constexpr double kShownCodes = 0.25;
// Cone vision only (Wang, Ji & Zhang 2011, eq. 20: photopic above 10^0.6 cd/m^2) where no cell
// of the view sphere is darker than 4 times that: a cell's mean hides its darker pixels.
inline constexpr double kPhotopicCdM2 = 3.98107;
inline constexpr double kPhotopicMargin = 4.0;
inline constexpr double kMoonlitSkyMargin = 10.0;
inline constexpr double kSunlitSkyMargin = 10.0;
inline constexpr double kNightLightMargin = 8.0;
// Point sources: a cell's mean hides its darker pixels, so the darkest cell's luminance is
// divided by this before its threshold is taken (Schaefer's threshold grows as sqrt(B) by day,
// so the brightest source must beat the darkest cell's threshold by about 3).
inline constexpr double kPointSourceMargin = 10.0;

struct ShownLayers {
  bool sunlitSky = true;
  bool moonlitSky = true;
  bool nightLight = true;
  bool mesopic = true;  // some of the view may be dim enough for rod vision (else photopic only)
  bool pointSources = true;  // some star or planet may be seen (the displayed-star pass is drawn)
  // lux: no star or planet at or below this can be seen anywhere in the view
  // (faintestPointSourceSeenLux); the displayed-star pass draws only those above it.
  double pointSourceFloorLux = 0.0;
};

// All true where a display has no tone curve (Tumblin-Rushmeier maps each pixel by itself) or
// there are no cells.
ShownLayers shownLayers(const std::vector<ViewCellLight>& cells, const std::vector<DisplayParams>& displays,
                        const std::vector<std::pair<DisplayParams, eye::ToneCurve>>& curves);

// Whether the brightest point source of the field (its illuminance at the eye, lux) can pass
// the eye's threshold anywhere on the view sphere: against the darkest cell's luminance over
// kPointSourceMargin (Schaefer 1990, physics/eye/point_source_visibility.glsl, the displayed-star
// pass's own test). True without cells.
bool pointSourcesSeen(const std::vector<ViewCellLight>& cells, double brightestLux);

// The illuminance at the eye (lux) a point source must exceed to pass the eye's threshold
// somewhere on the view sphere: Schaefer's threshold on the darkest cell's luminance over
// kPointSourceMargin. 0 without cells (every source may be seen).
double faintestPointSourceSeenLux(const std::vector<ViewCellLight>& cells);

// The displayed 8-bit code (0-255, unrounded) of a grey world luminance through `curve` on
// `display` (the tone pass's mapping, render/glsl/display_curve.glsl, for a grey).
double displayedCode(double worldCdM2, const eye::ToneCurve& curve, const DisplayParams& display);

}  // namespace skyig::sky
