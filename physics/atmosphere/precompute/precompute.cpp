#include "physics/atmosphere/precompute/precompute.h"

#include "physics/atmosphere/precompute/orders_tail.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace skyig::atmosphere {

static_assert(kMiePhaseSamples == shader::atmosphere_types::ATMOSPHERE_MIE_PHASE_SAMPLES);

using shader::cpu_texture::sampler2D;
using shader::cpu_texture::sampler3D;

AtmosphereParameters makeParameters(const Medium& medium,
                                    const std::array<double, 4>& wavelengthsNm,
                                    const TableSizes& sizes) {
  validate(medium);
  validate(sizes);
  AtmosphereParameters atm{};
  for (int i = 0; i < 4; ++i) {
    const SpectralCoefficients c = coefficientsAt(medium, wavelengthsNm[static_cast<std::size_t>(i)]);
    atm.solar_irradiance[i] = c.solarIrradiance;
    atm.rayleigh_scattering[i] = c.rayleighScattering;
    atm.mie_scattering[i] = c.mieScattering;
    atm.mie_extinction[i] = c.mieExtinction;
    atm.absorption_extinction[i] = c.ozoneAbsorption;
    atm.ground_albedo[i] = medium.groundAlbedo;
    atm.limb_darkening_exponent[i] = limbDarkeningExponent(wavelengthsNm[static_cast<std::size_t>(i)]);
  }
  atm.sun_angular_radius = medium.sunAngularRadiusRad;
  atm.bottom_radius = medium.bottomRadiusM;
  atm.top_radius = medium.topRadiusM;
  atm.rayleigh_scale_height = medium.rayleighScaleHeightM;
  atm.mie_scale_height = medium.mieScaleHeightM;
  atm.mie_phase_g = medium.miePhaseG;
  if (medium.aerosolType != AerosolType::bruneton2017) {
    const AerosolOptics optics = aerosolOptics(medium.aerosolType, medium.aerosolHumidity);
    atm.mie_phase_tabulated = 1.0;
    for (int i = 0; i < kMiePhaseSamples; ++i) atm.mie_phase_log_table[i] = optics.logPhase[static_cast<std::size_t>(i)];
  }
  atm.ozone_center_altitude = medium.ozoneCentreAltitudeM;
  atm.ozone_half_width = medium.ozoneHalfWidthM;
  atm.mu_s_min = std::cos(medium.maxSunZenithRad);
  atm.transmittance_width = sizes.transmittanceMu;
  atm.transmittance_height = sizes.transmittanceR;
  atm.irradiance_width = sizes.irradianceMuS;
  atm.irradiance_height = sizes.irradianceR;
  atm.scattering_r_size = sizes.scatteringR;
  atm.scattering_mu_size = sizes.scatteringMu;
  atm.scattering_mu_s_size = sizes.scatteringMuS;
  atm.scattering_nu_size = sizes.scatteringNu;
  return atm;
}

void parallelFor(int count, int threads, const std::function<void(int)>& fn) {
  int n = threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  n = std::max(1, std::min(n, count));
  std::atomic<int> next{0};
  std::exception_ptr error;
  std::mutex errorMutex;
  auto worker = [&] {
    for (int i = next++; i < count; i = next++) {
      try {
        fn(i);
      } catch (...) {
        std::lock_guard<std::mutex> lock(errorMutex);
        if (!error) error = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < n; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

namespace {

int size(double s) { return static_cast<int>(s); }

sampler2D make2D(double w, double h) { return sampler2D(size(w), size(h)); }

sampler3D makeScattering(const AtmosphereParameters& atm) {
  return sampler3D(size(atm.scattering_nu_size * atm.scattering_mu_s_size),
                   size(atm.scattering_mu_size), size(atm.scattering_r_size));
}

// Fills a 2D table texel by texel; rows in parallel. A cancelled pass skips its remaining rows
// and throws Cancelled.
template <typename Fn>
void fill2D(sampler2D& t, int threads, const CancelToken& cancel, Fn fn) {
  parallelFor(t.height, threads, [&](int y) {
    if (cancel.requested()) return;
    for (int x = 0; x < t.width; ++x) t.at(x, y) = fn(glm::dvec2(x + 0.5, y + 0.5));
  });
  cancel.throwIfRequested();
}

// Runs fn(x, y, z, frag_coord) over a 3D table; (z, y) rows in parallel, cancellable as fill2D.
template <typename Fn>
void for3D(const sampler3D& t, int threads, const CancelToken& cancel, Fn fn) {
  parallelFor(t.depth * t.height, threads, [&](int row) {
    if (cancel.requested()) return;
    const int z = row / t.height;
    const int y = row % t.height;
    for (int x = 0; x < t.width; ++x) fn(x, y, z, glm::dvec3(x + 0.5, y + 0.5, z + 0.5));
  });
  cancel.throwIfRequested();
}

}  // namespace

GroupTables precomputeGroup(const AtmosphereParameters& atm, const PrecomputeOptions& options,
                            const PrecomputeControl& control) {
  if (options.scatteringOrders < 1 || options.scatteringOrders > 32) {
    throw std::invalid_argument("atmosphere precompute: scattering_orders = " +
                                std::to_string(options.scatteringOrders) +
                                " is invalid (expected 1 to 32)");
  }
  const int threads = options.threads;
  const CancelToken& cancel = control.cancel;
  GroupTables out;

  // 1. Optical depth to the top of the atmosphere (the transmittance table).
  control.begin("transmittance");
  out.transmittance = make2D(atm.transmittance_width, atm.transmittance_height);
  fill2D(out.transmittance, threads, cancel,
         [&](const glm::dvec2& frag) { return shader::computeOpticalDepthTexel(atm, frag); });
  const sampler2D& transmittance = out.transmittance;

  // 2. Direct irradiance (order 0 on the ground): feeds order 2; not part of the sky table.
  control.begin("direct irradiance");
  sampler2D deltaIrradiance = make2D(atm.irradiance_width, atm.irradiance_height);
  fill2D(deltaIrradiance, threads, cancel,
         [&](const glm::dvec2& frag) { return shader::computeDirectIrradianceTexel(atm, transmittance, frag); });
  out.irradiance = make2D(atm.irradiance_width, atm.irradiance_height);

  // 3. Single scattering, Rayleigh and Mie apart.
  control.begin("single scattering");
  sampler3D deltaRayleigh = makeScattering(atm);
  sampler3D deltaMie = makeScattering(atm);
  for3D(deltaRayleigh, threads, cancel, [&](int x, int y, int z, const glm::dvec3& frag) {
    glm::dvec4 rayleigh;
    glm::dvec4 mie;
    shader::computeSingleScatteringTexel(atm, transmittance, frag, rayleigh, mie);
    deltaRayleigh.at(x, y, z) = rayleigh;
    deltaMie.at(x, y, z) = mie;
  });
  out.scattering = deltaRayleigh;
  out.singleMie = deltaMie;

  // 4. Orders 2..N, each from the previous one.
  sampler3D deltaMultiple = makeScattering(atm);
  sampler3D deltaDensity = makeScattering(atm);
  sampler3D before;  // the order before the last, for the tail
  for (int order = 2; order <= options.scatteringOrders; ++order) {
    const std::string orderText = ", order " + std::to_string(order) + "/" + std::to_string(options.scatteringOrders);
    control.begin("scattering density" + orderText);
    for3D(deltaDensity, threads, cancel, [&](int x, int y, int z, const glm::dvec3& frag) {
      deltaDensity.at(x, y, z) = shader::computeScatteringDensityTexel(
          atm, transmittance, deltaRayleigh, deltaMie, deltaMultiple, deltaIrradiance, frag,
          order);
    });
    control.begin("indirect irradiance" + orderText);
    fill2D(deltaIrradiance, threads, cancel, [&](const glm::dvec2& frag) {
      return shader::computeIndirectIrradianceTexel(atm, deltaRayleigh, deltaMie,
                                                    deltaMultiple, frag, order - 1);
    });
    for (std::size_t i = 0; i < out.irradiance.texels.size(); ++i) {
      out.irradiance.texels[i] += deltaIrradiance.texels[i];
    }
    control.begin("multiple scattering" + orderText);
    const bool tail = options.ordersTail && order == options.scatteringOrders && order >= 3;
    if (tail) before = deltaMultiple;
    for3D(deltaMultiple, threads, cancel, [&](int x, int y, int z, const glm::dvec3& frag) {
      double nu = 0.0;
      const glm::dvec4 radiance =
          shader::computeMultipleScatteringTexel(atm, transmittance, deltaDensity, frag, nu);
      deltaMultiple.at(x, y, z) = radiance;
      out.scattering.at(x, y, z) += radiance / shader::rayleighPhaseFunction(nu);
    });
    if (tail) addOrdersTail(atm, before, deltaMultiple, deltaIrradiance, out);
  }
  return out;
}

}  // namespace skyig::atmosphere
