#include "sky/view_sphere.h"

#include "physics/atmosphere/physical_camera.h"
#include "sky/sky_state.h"
#include "physics/physics.h"

#include <array>
#include <cmath>
#include <numbers>
#include <optional>

namespace skyig::sky {

namespace {

constexpr int kMu = 16, kPhi = 32;  // cells over the whole sphere, equal solid angle each
constexpr double kPi = std::numbers::pi;

// Distance along `view` to the ground, or kFar when the view misses it.
constexpr double kFar = 1e9;
double groundDistance(const atmosphere::AtmosphereModel& model, const glm::dvec3& camera, const glm::dvec3& view) {
  const double r = glm::length(camera), rmu = glm::dot(camera, view);
  const double bottom = model.parameters(0).bottom_radius;
  const double discriminant = rmu * rmu - r * r + bottom * bottom;
  return rmu < 0.0 && discriminant >= 0.0 ? -rmu - std::sqrt(discriminant) : kFar;
}

// Luminance the physical model gives along `view` for a light of the sun's brightness in
// direction `light`: the sky, or the ground (d metres on) with its aerial perspective.
double physicalLuminance(const atmosphere::AtmosphereModel& model, const glm::dvec3& camera, const glm::dvec3& view,
                         const glm::dvec3& light, double d) {
  if (d < kFar) return model.converter().luminance(model.groundRadiance(camera, camera + view * d, light));
  return model.converter().luminance(model.skyRadiance(camera, view, light));
}

}  // namespace

ViewSphere viewSphere(const SkyState& s) {
  ViewSphere out;
  eye::LuminanceHistogram& h = out.histogram;
  double sum = 0.0;
  const atmosphere::AtmosphereModel* model =
      s.conditions.model == SkyModel::Physical ? s.conditions.atmosphere.get() : nullptr;
  const glm::dvec3 sun = enuDirection(s.sunAzimuth, s.sunAltitude);
  const glm::dvec3 camera = model ? atmosphere::physicalCamera(*model, s.observer.heightM) : glm::dvec3(0.0);
  const double moonScale = shader::rec709Luminance(s.moonlightScale);
  // The night's diffuse light (airglow, zodiacal light; the Milky Way is a few percent of it and
  // left out here), with the unresolved starlight's floor at the poles.
  std::optional<night::NightDiffuseSky> night;
  if (s.ephemeris) night = night::makeNightDiffuseSky(*s.ephemeris, s.extinction, false);
  auto cells = std::make_shared<std::vector<ViewCellLight>>();
  cells->reserve(kMu * kPhi);
  const weather::FogLayers moonFog = moonlitFogLayers(s.fog);
  const double fogHeight = model ? glm::length(camera) - model->parameters(0).bottom_radius : 0.0;
  const weather::AirTransmittance air = model ? airTransmittanceFrom(*model, fogHeight) : nullptr;
  forEachEqualAreaCell(kMu, kPhi, [&](const glm::dvec3& view, double cell) {
    double sunlit = 0.0, moonlit = 0.0, own = 0.0;
    const double d = model ? groundDistance(*model, camera, view) : kFar;
    if (model) {
      sunlit = physicalLuminance(*model, camera, view, sun, d);
      if (moonScale > 0.0) moonlit = moonScale * physicalLuminance(*model, camera, view, s.moonDirection, d);
    } else {
      sunlit = shader::rec709Luminance(analyticSkyLightOnly(s.sky.params, view));
    }
    if (night && view.z > 0.0) own = shader::rec709Luminance(night::nightDiffuseRadianceWithoutMap(*night, view));
    if (view.z < 0.0) own = shader::rec709Luminance(s.nightGroundRadiance);
    if (s.fog.any()) {  // the sky pass's composite (physics/weather/fog_layer.glsl), per light;
      // the night's own light came through the fog already (the state's extinction profile)
      sunlit = throughFogLayers(s.fog.sunlit, sunlit, fogHeight, view.z, d, air);
      moonlit = throughFogLayers(moonFog, moonlit, fogHeight, view.z, d, air);
    }
    const double l = sunlit + moonlit + own;
    cells->push_back({static_cast<float>(sunlit), static_cast<float>(moonlit), static_cast<float>(own)});
    h.add(l, cell);
    sum += l;
  });
  out.meanLuminance = sum / (kMu * kPhi);
  out.cells = std::move(cells);
  double brightest = 0.0;
  for (int i = eye::LuminanceHistogram::kBins - 1; i >= 0 && brightest == 0.0; --i)
    if (h.weight[static_cast<std::size_t>(i)] > 0.0)
      brightest = h.minLog10 + (i + 1) * (h.maxLog10 - h.minLog10) / eye::LuminanceHistogram::kBins;
  h.highlightLog10 = brightest;  // the discs added below are highlights
  // The discs: their luminance over their solid angle (a part of a cell each).
  const double sunRadius = model ? model->parameters(0).sun_angular_radius : 0.2666 * kPi / 180.0;
  const double sunDisc = model ? model->converter().luminance(model->sunDiscRadiance(camera, sun, sun))
                               : shader::rec709Luminance(s.sky.params.sunRadiance);
  // A disc no brighter than the sky around it (the moon by day, the sun below the horizon seen
  // through the earth) is not a highlight and, a few millionths of the sphere, changes nothing
  // else; left out, it cannot stretch the scene's range downwards.
  auto addHighlight = [&](double cdM2, double solidAngle) {
    if (std::log10(std::max(cdM2, 1e-30)) > brightest) h.add(cdM2, solidAngle);
  };
  addHighlight(sunDisc, kPi * sunRadius * sunRadius);
  if (s.moonDisc) {
    const night::MoonRadiance m = night::moonDiscRadiance(*s.moonDisc, s.moonDisc->centreSeen);
    addHighlight(m.luminanceCdM2, kPi * s.moonDisc->angularRadiusRad * s.moonDisc->angularRadiusRad);
  }
  return out;
}

}  // namespace skyig::sky
