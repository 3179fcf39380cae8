#include "sky/client_light.h"

#include "physics/weather/fog_table.h"

#include "physics/analytic/analytic_sky.h"
#include "physics/atmosphere/physical_camera.h"
#include "physics/atmosphere/probe.h"
#include "physics/moon/moon_disc.h"
#include "physics/night/night_diffuse.h"
#include "physics/stars/star_field.h"
#include "sky/sky_state.h"
#include "sky/view_sphere.h"
#include "physics/physics.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace skyig::sky {

namespace {

// The quadrature of the sphere: cells of equal solid angle, kMu bands in cos(zenith) (half of
// them above the horizon) x kPhi in azimuth, evaluated at their centres.
constexpr int kMu = 32, kPhi = 64;

double luminance(const glm::dvec3& c) { return shader::rec709Luminance(c); }

glm::dvec3 colourOf(const glm::dvec3& rec709) {
  const double y = luminance(rec709);
  return y > 0.0 ? rec709 / y : glm::dvec3(1.0);
}

// Ramamoorthi & Hanrahan (2001), eq. 3: the real SH basis Y_lm(x, y, z) for l <= 2, in the order
// of ShCoefficients.
std::array<double, 9> shBasis(const glm::dvec3& d) {
  const double x = d.x, y = d.y, z = d.z;
  return {0.282095,
          0.488603 * y,
          0.488603 * z,
          0.488603 * x,
          1.092548 * x * y,
          1.092548 * y * z,
          0.315392 * (3.0 * z * z - 1.0),
          1.092548 * x * z,
          0.546274 * (x * x - y * y)};
}

// A ray's length past any ground or layer: "to the top of the atmosphere and beyond".
constexpr double kBeyondTheGround = 1e9;

ClientDirectLight physicalSun(const SkyState& s, const atmosphere::AtmosphereModel& model, const glm::dvec3& camera) {
  ClientDirectLight out;
  out.direction = enuDirection(s.sunAzimuth, s.sunAltitude);
  // The horizontal figure is the probe's (one piece of code); facing the sun, the same
  // evaluation with the sun as the normal.
  out.horizontalLux = atmosphere::horizontalIrradiance(model, camera, out.direction).directSunLux;
  const atmosphere::Spectrum normal = model.sunIrradiance(camera, out.direction, out.direction);
  out.normalLux = model.converter().luminance(normal);
  out.colour = colourOf(model.converter().toRec709(normal));
  // Through the fog layers on the way to the sun (grey: the colour stays).
  const double t = fogTransmittanceToSpaceAlong(s.fog, model, s.observer.heightM, out.direction);
  out.horizontalLux *= t;
  out.normalLux *= t;
  return out;
}

ClientDirectLight analyticSun(const SkyState& s) {
  ClientDirectLight out;
  out.direction = enuDirection(s.sunAzimuth, s.sunAltitude);
  const glm::dvec3 horizontal = s.sky.lighting.directHorizontal;
  out.horizontalLux = luminance(horizontal);
  out.colour = colourOf(horizontal);
  out.normalLux = out.direction.z > 0.0 ? out.horizontalLux / out.direction.z : 0.0;
  return out;
}

ClientDirectLight moon(const SkyState& s) {
  ClientDirectLight out;
  out.direction = s.moonDirection;
  out.horizontalLux = moonIlluminanceLux(s);  // the probe's moon_lux
  if (s.moonDisc) {
    const glm::dvec3 normal = night::moonNormalIlluminanceRec709(*s.moonDisc);
    out.normalLux = luminance(normal);
    out.colour = colourOf(normal);
  }
  return out;
}

}  // namespace

glm::dvec3 clientSkyRadiance(const SkyState& s, const atmosphere::AtmosphereModel* model, const glm::dvec3& view) {
  if (!model) return analyticSkyLightOnly(s.sky.params, view);
  const glm::dvec3 camera = atmosphere::physicalCamera(*model, s.observer.heightM);
  const glm::dvec3 sun = enuDirection(s.sunAzimuth, s.sunAltitude);
  // The ground where the ray meets it (as the view sphere and the probe find it), else the sky.
  const double r = glm::length(camera), rmu = glm::dot(camera, view);
  const double bottom = model->parameters(0).bottom_radius;
  const double discriminant = rmu * rmu - r * r + bottom * bottom;
  const bool ground = rmu < 0.0 && discriminant >= 0.0;
  const double d = ground ? -rmu - std::sqrt(discriminant) : kBeyondTheGround;
  auto radiance = [&](const glm::dvec3& light) {
    if (ground) return model->converter().toRec709(model->groundRadiance(camera, camera + view * d, light));
    return model->converter().toRec709(model->skyRadiance(camera, view, light));
  };
  glm::dvec3 out = radiance(sun);
  // The moonlit sky (Jensen et al. 2001): the same sky lit from the moon, scaled per channel.
  if (luminance(s.moonlightScale) > 0.0) out += radiance(s.moonDirection) * s.moonlightScale;
  // Then the fog in front, as the sky pass composes it (physics/weather/fog_layer.glsl).
  const glm::dvec4 fog = weather::fogAlong(drawnFogLayers(s.fog), r - bottom, view.z, d, airTransmittanceFrom(*model, r - bottom));
  return out * fog.a + glm::dvec3(fog);
}

glm::dvec3 shIrradiance(const ShCoefficients& L, const glm::dvec3& n) {
  // Ramamoorthi & Hanrahan (2001), eq. 12's constants and eq. 13.
  constexpr double c1 = 0.429043, c2 = 0.511664, c3 = 0.743125, c4 = 0.886227, c5 = 0.247708;
  const double x = n.x, y = n.y, z = n.z;
  return c1 * L[8] * (x * x - y * y) + c3 * L[6] * z * z + c4 * L[0] - c5 * L[6] +
         2.0 * c1 * (L[4] * x * y + L[7] * x * z + L[5] * y * z) + 2.0 * c2 * (L[3] * x + L[1] * y + L[2] * z);
}

ClientLight clientLight(const SkyState& s, const atmosphere::AtmosphereModel* model) {
  ClientLight out;
  if (model) {
    out.sun = physicalSun(s, *model, atmosphere::physicalCamera(*model, s.observer.heightM));
  } else {
    out.sun = analyticSun(s);
  }
  out.moon = moon(s);
  out.adaptationLuminance = s.worldAdaptationLuminance;
  out.adaptationGain = s.adaptationGain;

  // One pass over the sphere: E = integral of L cos(theta) over the upper hemisphere, and
  // L_lm = integral of L Y_lm over the sphere (Ramamoorthi & Hanrahan 2001, eq. 4).
  // Above the horizon also the night's own diffuse light (airglow, zodiacal light, the Milky
  // Way's and the unresolved stars' floor: physics/night/night_diffuse.h), which lights the terrain
  // on a moonless night; the resolved stars, point sources, add their illuminance to the
  // horizontal ambient only (physics/stars/star_field.h).
  std::optional<night::NightDiffuseSky> night;
  if (s.ephemeris) night = night::makeNightDiffuseSky(*s.ephemeris, s.extinction, /*withMilkyWay=*/false);
  glm::dvec3 horizontal = s.starField ? night::horizontalIlluminance(*s.starField) : glm::dvec3(0.0);
  ShCoefficients sh{};
  forEachEqualAreaCell(kMu, kPhi, [&](const glm::dvec3& view, double cell) {
    glm::dvec3 l = clientSkyRadiance(s, model, view);
    if (night && view.z > 0.0) l += night::nightDiffuseRadianceWithoutMap(*night, view);
    if (view.z > 0.0) horizontal += l * view.z * cell;
    const std::array<double, 9> y = shBasis(view);
    for (std::size_t k = 0; k < sh.size(); ++k) sh[k] += l * y[k] * cell;
  });
  out.ambientHorizontalRec709 = horizontal;
  out.ambientHorizontalLux = luminance(horizontal);
  out.skySh = sh;
  return out;
}

ClientAerialPerspective clientAerialPerspective(const SkyState& s, const atmosphere::AtmosphereModel& model,
                                            const glm::dvec3& offsetEnu) {
  const glm::dvec3 camera = atmosphere::physicalCamera(model, s.observer.heightM);
  // The ENU frame at the camera is the model's frame (the camera on the +z axis).
  const glm::dvec3 point = camera + offsetEnu;
  const glm::dvec3 sun = enuDirection(s.sunAzimuth, s.sunAltitude);
  ClientAerialPerspective out;
  atmosphere::Spectrum t;
  out.inScattered = model.converter().toRec709(model.skyRadianceToPoint(camera, point, sun, &t));
  if (luminance(s.moonlightScale) > 0.0)
    out.inScattered += model.converter().toRec709(model.skyRadianceToPoint(camera, point, s.moonDirection)) * s.moonlightScale;
  // Per channel for sunlight: the Rec.709 of the sun's spectrum through the segment over that of
  // the sun's spectrum.
  const atmosphere::Spectrum solar = model.solarRadiance();
  atmosphere::Spectrum through(solar.size());
  for (std::size_t i = 0; i < solar.size(); ++i) through[i] = solar[i] * t.at(i);
  const glm::dvec3 before = model.converter().toRec709(solar), after = model.converter().toRec709(through);
  for (int c = 0; c < 3; ++c) out.transmittance[c] = before[c] > 0.0 ? std::clamp(after[c] / before[c], 0.0, 1.0) : 1.0;
  // The fog layers on the segment, as the sky pass composes them: what lies behind them (the
  // surface, the air's light) dimmed, their own light added.
  const double h = glm::length(camera) - model.parameters(0).bottom_radius;
  const double d = glm::length(offsetEnu), mu = d > 0.0 ? offsetEnu.z / d : 1.0;
  const glm::dvec4 fog = weather::fogAlong(drawnFogLayers(s.fog), h, mu, d, airTransmittanceFrom(model, h));
  out.inScattered = out.inScattered * fog.a + glm::dvec3(fog);
  out.transmittance *= fog.a;
  return out;
}

}  // namespace skyig::sky
