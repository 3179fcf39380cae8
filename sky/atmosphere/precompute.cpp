#include "sky/atmosphere/precompute.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace skyig::atmosphere {

using shader::cpu_texture::sampler2D;
using shader::cpu_texture::sampler3D;

AtmosphereParameters makeParameters(const Medium& medium,
                                    const std::array<double, 4>& wavelengths_nm,
                                    const TableSizes& sizes) {
  validate(medium);
  validate(sizes);
  AtmosphereParameters atm{};
  for (int i = 0; i < 4; ++i) {
    const SpectralCoefficients c = coefficientsAt(medium, wavelengths_nm[static_cast<std::size_t>(i)]);
    atm.solar_irradiance[i] = c.solar_irradiance;
    atm.rayleigh_scattering[i] = c.rayleigh_scattering;
    atm.mie_scattering[i] = c.mie_scattering;
    atm.mie_extinction[i] = c.mie_extinction;
    atm.absorption_extinction[i] = c.ozone_absorption;
    atm.ground_albedo[i] = medium.ground_albedo;
    atm.limb_darkening_exponent[i] = limbDarkeningExponent(wavelengths_nm[static_cast<std::size_t>(i)]);
  }
  atm.sun_angular_radius = medium.sun_angular_radius_rad;
  atm.bottom_radius = medium.bottom_radius_m;
  atm.top_radius = medium.top_radius_m;
  atm.rayleigh_scale_height = medium.rayleigh_scale_height_m;
  atm.mie_scale_height = medium.mie_scale_height_m;
  atm.mie_phase_g = medium.mie_phase_g;
  atm.ozone_center_altitude = medium.ozone_center_altitude_m;
  atm.ozone_half_width = medium.ozone_half_width_m;
  atm.mu_s_min = std::cos(medium.max_sun_zenith_rad);
  atm.transmittance_width = sizes.transmittance_mu;
  atm.transmittance_height = sizes.transmittance_r;
  atm.irradiance_width = sizes.irradiance_mu_s;
  atm.irradiance_height = sizes.irradiance_r;
  atm.scattering_r_size = sizes.scattering_r;
  atm.scattering_mu_size = sizes.scattering_mu;
  atm.scattering_mu_s_size = sizes.scattering_mu_s;
  atm.scattering_nu_size = sizes.scattering_nu;
  return atm;
}

void parallelFor(int count, int threads, const std::function<void(int)>& fn) {
  int n = threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  n = std::max(1, std::min(n, count));
  std::atomic<int> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto worker = [&] {
    for (int i = next++; i < count; i = next++) {
      try {
        fn(i);
      } catch (...) {
        std::lock_guard<std::mutex> lock(error_mutex);
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

// Fills a 2D table texel by texel; rows in parallel.
template <typename Fn>
void fill2D(sampler2D& t, int threads, Fn fn) {
  parallelFor(t.height, threads, [&](int y) {
    for (int x = 0; x < t.width; ++x) t.at(x, y) = fn(glm::dvec2(x + 0.5, y + 0.5));
  });
}

// Runs fn(x, y, z, frag_coord) over a 3D table; (z, y) rows in parallel.
template <typename Fn>
void for3D(const sampler3D& t, int threads, Fn fn) {
  parallelFor(t.depth * t.height, threads, [&](int row) {
    const int z = row / t.height;
    const int y = row % t.height;
    for (int x = 0; x < t.width; ++x) fn(x, y, z, glm::dvec3(x + 0.5, y + 0.5, z + 0.5));
  });
}

}  // namespace

GroupTables precomputeGroup(const AtmosphereParameters& atm, const PrecomputeOptions& options) {
  if (options.scattering_orders < 1 || options.scattering_orders > 32) {
    throw std::invalid_argument("atmosphere precompute: scattering_orders = " +
                                std::to_string(options.scattering_orders) +
                                " is invalid (expected 1 to 32)");
  }
  const int threads = options.threads;
  GroupTables out;

  // 1. Transmittance to the top of the atmosphere.
  out.transmittance = make2D(atm.transmittance_width, atm.transmittance_height);
  fill2D(out.transmittance, threads, [&](const glm::dvec2& frag) {
    return shader::computeTransmittanceTexel(atm, frag);
  });
  const sampler2D& transmittance = out.transmittance;

  // 2. Direct irradiance (order 0 on the ground): feeds order 2; not part of the sky table.
  sampler2D delta_irradiance = make2D(atm.irradiance_width, atm.irradiance_height);
  fill2D(delta_irradiance, threads, [&](const glm::dvec2& frag) {
    return shader::computeDirectIrradianceTexel(atm, transmittance, frag);
  });
  out.irradiance = make2D(atm.irradiance_width, atm.irradiance_height);

  // 3. Single scattering, Rayleigh and Mie apart.
  sampler3D delta_rayleigh = makeScattering(atm);
  sampler3D delta_mie = makeScattering(atm);
  for3D(delta_rayleigh, threads, [&](int x, int y, int z, const glm::dvec3& frag) {
    glm::dvec4 rayleigh;
    glm::dvec4 mie;
    shader::computeSingleScatteringTexel(atm, transmittance, frag, rayleigh, mie);
    delta_rayleigh.at(x, y, z) = rayleigh;
    delta_mie.at(x, y, z) = mie;
  });
  out.scattering = delta_rayleigh;
  out.single_mie = delta_mie;

  // 4. Orders 2..N, each from the previous one.
  sampler3D delta_multiple = makeScattering(atm);
  sampler3D delta_density = makeScattering(atm);
  for (int order = 2; order <= options.scattering_orders; ++order) {
    for3D(delta_density, threads, [&](int x, int y, int z, const glm::dvec3& frag) {
      delta_density.at(x, y, z) = shader::computeScatteringDensityTexel(
          atm, transmittance, delta_rayleigh, delta_mie, delta_multiple, delta_irradiance, frag,
          order);
    });
    fill2D(delta_irradiance, threads, [&](const glm::dvec2& frag) {
      return shader::computeIndirectIrradianceTexel(atm, delta_rayleigh, delta_mie,
                                                    delta_multiple, frag, order - 1);
    });
    for (std::size_t i = 0; i < out.irradiance.texels.size(); ++i) {
      out.irradiance.texels[i] += delta_irradiance.texels[i];
    }
    for3D(delta_multiple, threads, [&](int x, int y, int z, const glm::dvec3& frag) {
      double nu = 0.0;
      const glm::dvec4 radiance =
          shader::computeMultipleScatteringTexel(atm, transmittance, delta_density, frag, nu);
      delta_multiple.at(x, y, z) = radiance;
      out.scattering.at(x, y, z) += radiance / shader::rayleighPhaseFunction(nu);
    });
  }
  return out;
}

}  // namespace skyig::atmosphere
