#pragma once
// A precomputed atmosphere at all of its wavelengths: the medium, the spectral sampling, the
// tables of every group of four wavelengths, and spectral evaluation of the rendering
// functions on the CPU (probe, eye adaptation, tests). Positions are metres from the planet's
// centre; directions are unit vectors.
//
// Names in sky/atmosphere follow skyig's C++ style (UpperCamel types, lowerCamel functions,
// variables and members: Medium::topRadiusM, TableSizes::scatteringMu). The exception is what
// comes from the GLSL compiled as C++ (physics/atmosphere/*.glsl through
// physics/atmosphere/atmosphere_physics.h): AtmosphereParameters' members (top_radius, mie_phase_g, ...)
// and the shader code keep the snake_case of Bruneton's 2017 implementation, because one source
// serves the GPU and the CPU. Text for outside keeps snake_case too: TOML keys, the probe's JSON
// keys, and the names error messages give bad values.
#include <glm/vec3.hpp>

#include <optional>
#include <vector>

#include "physics/atmosphere/precompute/precompute.h"
#include "physics/spectrum/spectrum.h"

namespace skyig::atmosphere {

using Spectrum = std::vector<double>;  // one value per wavelength of the model

struct ModelConfig {
  Medium medium;
  std::vector<double> wavelengthsNm = defaultWavelengths();
  TableSizes sizes;
  PrecomputeOptions options;
};

// The shader-side parameters of each group of four wavelengths of `config`, the last group
// padded by repeating the last wavelength; validates the medium and the sizes (throws
// std::invalid_argument). The CPU and GPU precomputes and the model all group them so.
std::vector<AtmosphereParameters> groupParameters(const ModelConfig& config);

class AtmosphereModel {
 public:
  // Precomputes every group's tables (throws std::invalid_argument on a bad config).
  explicit AtmosphereModel(const ModelConfig& config);
  // Adopts tables computed before (the disk cache); throws if they do not fit the config.
  AtmosphereModel(const ModelConfig& config, std::vector<GroupTables> tables);

  const ModelConfig& config() const { return config_; }
  const std::vector<double>& wavelengths() const { return config_.wavelengthsNm; }
  const SpectralConverter& converter() const { return converter_; }
  std::size_t groupCount() const { return tables_.size(); }
  const GroupTables& tables(std::size_t group) const { return tables_.at(group); }
  const AtmosphereParameters& parameters(std::size_t group) const { return params_.at(group); }

  // Set when the tables are not the config's own but blended from two cached visibility steps
  // (visibility_blend.h), standing in while the exact ones are built; what a state dump says.
  struct BlendOrigin {
    double clearerKm;  // the steps' visibilities (equal when the nearest step stands in alone)
    double hazierKm;
    double weight;     // of the hazier step
  };
  const std::optional<BlendOrigin>& blendOrigin() const { return blendOrigin_; }
  void setBlendOrigin(const BlendOrigin& origin) { blendOrigin_ = origin; }

  // Light scattered into the view ray up to the ground or space; *transmittance (if given)
  // is that of the whole ray, zero when it hits the ground.
  Spectrum skyRadiance(const glm::dvec3& camera, const glm::dvec3& view, const glm::dvec3& sun,
                       Spectrum* transmittance = nullptr) const;
  // Light scattered between camera and point; *transmittance of that segment.
  Spectrum skyRadianceToPoint(const glm::dvec3& camera, const glm::dvec3& point,
                              const glm::dvec3& sun, Spectrum* transmittance = nullptr) const;
  // Radiance of the ground point seen from the camera, with its aerial perspective.
  Spectrum groundRadiance(const glm::dvec3& camera, const glm::dvec3& groundPoint,
                          const glm::dvec3& sun, Spectrum* transmittance = nullptr) const;
  // Direct sun and sky irradiance on a surface at `point` with the given normal.
  Spectrum sunIrradiance(const glm::dvec3& point, const glm::dvec3& normal,
                         const glm::dvec3& sun) const;
  Spectrum skyIrradiance(const glm::dvec3& point, const glm::dvec3& normal,
                         const glm::dvec3& sun) const;
  // Transmittance from (r, mu) to the top of the atmosphere (0 below the horizon's ground).
  Spectrum transmittanceToTop(double r, double mu) const;
  // Radiance of the sun disc outside the atmosphere (uniform disc).
  Spectrum solarRadiance() const;
  // The sun disc seen along `view`: limb darkened and attenuated; zero off the disc.
  Spectrum sunDiscRadiance(const glm::dvec3& camera, const glm::dvec3& view,
                           const glm::dvec3& sun) const;

 private:
  void setUp();
  template <typename Fn>
  Spectrum perGroup(Fn fn, Spectrum* second = nullptr) const;

  ModelConfig config_;
  SpectralConverter converter_;
  std::vector<AtmosphereParameters> params_;
  std::vector<GroupTables> tables_;
  std::optional<BlendOrigin> blendOrigin_;
};

// Position of an observer at `altitudeM` above the ground on the +z axis, and directions
// from zenith and azimuth angles in radians (azimuth from +x towards +y).
glm::dvec3 observerPosition(const Medium& medium, double altitudeM);
glm::dvec3 directionFromAngles(double zenithRad, double azimuthRad);

}  // namespace skyig::atmosphere
