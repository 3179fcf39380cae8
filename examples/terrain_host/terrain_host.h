#pragma once
// A tiny image generator of its own that embeds skyig (docs/library.md): a terrain lit by
// skyig's sun, moon and sky ambient (skyig::Sky::light), fogged by its aerial perspective
// (per fragment, skyig::SkyDraw::aerialPerspectiveGlsl in its own shader), drawn first with its depth buffer, and the sky
// drawn behind it by skyig::SkyDraw where the terrain left the far plane. All linear light in
// cd/m^2 (the host tone-maps with skyig's adaptation), so the sky and the terrain share one
// exposure.
#include <skyig/gl_sky.h>
#include <skyig/sky.h>

#include <array>
#include <string>
#include <vector>

namespace terrain_host {

using Mat4 = std::array<float, 16>;  // column-major, as GL takes it

// The view from the observer's east-north-up frame to GL eye space for a compass heading and a
// pitch, and a symmetric perspective: reverse-Z with an infinite far plane (window depth 1 at
// `near`, 0 at infinity, with glClipControl's zero-to-one depth) or GL's standard one.
Mat4 viewMatrix(double yawDeg, double pitchDeg);
Mat4 projectionMatrix(double horizontalFovDeg, double aspect, double near, double far, skyig::DepthConvention depth);

struct Options {
  int width = 320;
  int height = 200;
  double eyeHeightM = 300.0;   // above the flat terrain
  double yawDeg = 180.0;       // compass heading of the view
  double pitchDeg = -2.0;
  double horizontalFovDeg = 60.0;
  double terrainRadiusM = 300000.0;
  std::array<double, 3> albedo{0.10, 0.12, 0.06};  // Lambertian reflectance per Rec.709 channel: grass and soil
  skyig::DepthConvention depth = skyig::DepthConvention::ReverseZ;
};

// A frame: linear Rec.709 cd/m^2, rows bottom-up (GL's order), RGB per pixel.
struct Frame {
  int width = 0;
  int height = 0;
  std::vector<float> terrainOnly;  // before the sky was drawn (the clear colour where no terrain)
  std::vector<float> final;        // with the sky behind the terrain
  std::vector<float> depth;        // window depth after the terrain
  std::vector<float> distanceM;    // the terrain's distance per pixel (0 where none)
  double farDepth = 0.0;           // the depth buffer's clear value (the far plane)
};

// Draws a frame with the GL context current (OpenGL 4.5 core): the terrain of `sky`'s last
// update, then the sky. Throws std::runtime_error (or skyig::Error) naming what failed.
Frame drawFrame(const skyig::Sky& sky, const Options& options, skyig::GlProcAddress getProcAddress);

// A headless OpenGL 4.5 core context through EGL (no display server), current on this thread
// while it lives.
class HeadlessContext {
 public:
  HeadlessContext();
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;
  static skyig::GlProcAddress procAddress();

 private:
  void* display_ = nullptr;
  void* context_ = nullptr;
};

// Host tone mapping of a linear frame to 8-bit sRGB with skyig's adaptation luminance: an
// exposure that puts the adaptation level at mid-grey, then a Reinhard curve.
std::vector<unsigned char> toneMap(const std::vector<float>& rgb, double adaptationLuminance);

}  // namespace terrain_host
