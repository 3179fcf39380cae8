#pragma once
// A display channel of the node: an eyepoint rotation in the body frame, a frustum, a
// resolution and the display (projector) it is shown on.
#include "sky/camera.h"

#include <cmath>
#include <string>

namespace skyig::sky {

// How world luminance becomes display luminance (docs/tone-reproduction.md).
enum class ToneOperator {
  Histogram,         // Ward Larson, Rushmeier & Piatko 1997: visibility matching (the default)
  TumblinRushmeier,  // Tumblin & Rushmeier 1993: brightness matching
};

// Wang, Ji & Zhang 2011, eq. 17 (after Tumblin & Rushmeier 1993): L_d = L_amb + L_dmax n^gamma,
// and the viewer's adaptation to the display.
struct DisplayParams {
  ToneOperator toneOperator = ToneOperator::Histogram;
  double maxLuminance = 100.0;        // L_dmax, cd/m^2
  double ambientLuminance = 0.1;      // L_amb, cd/m^2
  double gamma = 2.2;
  // L_a(d), cd/m^2: the viewer adapts to what the screen shows on average, about a tenth of its
  // peak for projected sky scenes; with L_a(d) = L_dmax / 2 the Tumblin-Rushmeier operator puts
  // the mean daylight sky above L_dmax (docs/tone-reproduction.md).
  double viewerAdaptationLuminance = 10.0;
  bool operator==(const DisplayParams&) const = default;
};

// The channel sizes skyig renders, per side. GL 4.5 guarantees 16384-texel textures, but one
// 16384 x 16384 float RGBA target alone is 4 GiB (the sky pass keeps several): refused when the
// size is given (exit 2), not when the render target cannot be made (exit 3).
inline constexpr int kMinChannelSide = 16;
inline constexpr int kMaxChannelSide = 8192;

// The spectral band a channel's passes render: the eye's (luminance and colour, linear Rec.709
// cd/m^2) or a night-vision goggle's NVIS-weighted radiance (MIL-STD-3009's class A or B
// response), written equally into the three colour channels of the HDR target.
enum class SpectralBand { Visible, NvisClassA, NvisClassB };

// The phosphor of a goggle's screen: P43 (Gd2O2S:Tb, green, the usual one) or P45 (Y2O2S:Tb,
// "white phosphor").
enum class Phosphor { P43, P45 };

// A night-vision goggle (image intensifier) in front of a channel: what the host switches on
// with CIGI Sensor Control, and the configuration's [channel.goggle]
// (render/passes/goggle/goggle_pass.h, docs/nvis.md). The channel is a goggle while its `band` is not
// Visible; the goggle's class is then its band.
struct GoggleParams {
  SpectralBand nvisClass = SpectralBand::NvisClassA;  // the band when the goggle is switched on
  Phosphor phosphor = Phosphor::P43;
  double fieldOfViewDeg = 40.0;  // circular, centred on the channel's view direction
  bool automaticGain = true;     // automatic brightness control (ABC)
  double gain = 1.0;             // without ABC: the tube's gain as a fraction of its maximum, (0, 1]
  bool operator==(const GoggleParams&) const = default;
};

struct ChannelConfig {
  std::string name = "front";
  Attitude offset;
  Frustum frustum;
  int width = 1280;
  int height = 1024;
  std::string monitor;  // `serve` in windows: fullscreen on this monitor (GLFW's name); "" windowed
  DisplayParams display;
  SpectralBand band = SpectralBand::Visible;  // not Visible: the channel is a goggle of this class
  GoggleParams goggle;
};

inline bool isGoggle(const ChannelConfig& c) { return c.band != SpectralBand::Visible; }

// A goggle's frustum on `c`'s render size: the goggle's circular field fills the channel's
// height (half-angle fieldOfViewDeg / 2 up and down) and the width follows the aspect; outside
// the circle the goggle shows its housing, black.
inline Frustum goggleFrustum(const ChannelConfig& c) {
  const double halfRad = c.goggle.fieldOfViewDeg / 2.0 * 3.14159265358979323846 / 180.0;
  const double sideDeg = std::atan(std::tan(halfRad) * c.width / c.height) * 180.0 / 3.14159265358979323846;
  Frustum f;
  f.upDeg = f.downDeg = c.goggle.fieldOfViewDeg / 2.0;
  f.leftDeg = f.rightDeg = sideDeg;
  return f;
}

}  // namespace skyig::sky
