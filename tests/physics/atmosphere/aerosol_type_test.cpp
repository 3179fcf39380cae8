// The OPAC aerosol types (physics/atmosphere/aerosol_type.h): OPAC's own figures, the tabulated
// phase function the shaders interpolate, and the conditions that grow and thin the aerosol.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/atmosphere/aerosol_type.h"
#include "physics/atmosphere/atmosphere_physics.h"
#include "physics/atmosphere/conditions.h"
#include "physics/atmosphere/precompute/precompute.h"

namespace skyig::atmosphere {
namespace {

constexpr AerosolType kOpacTypes[] = {
    AerosolType::continentalClean, AerosolType::continentalAverage, AerosolType::continentalPolluted,
    AerosolType::urban,            AerosolType::desert,             AerosolType::maritimeClean,
    AerosolType::maritimePolluted, AerosolType::maritimeTropical,   AerosolType::arctic,
    AerosolType::antarctic};

AtmosphereParameters parametersOf(AerosolType type, double rh) {
  return makeParameters(withAerosolType(Medium{}, type, rh), {440.0, 550.0, 680.0, 830.0}, TableSizes::small());
}

// OPAC's program, asked for its continental polluted type at 80% and 0.55 um, prints
// ext.coef 1.746E-01 /km, sisc.alb 8.925E-01, asym.par 6.977E-01 (and a visibility of 16.12 km):
// the mixture of its components as skyig's derivation mixes them gives the same.
TEST(AerosolType, ContinentalPollutedAt80PercentIsOpacsOwnOutput) {
  const AerosolOptics o = aerosolOptics(AerosolType::continentalPolluted, 0.8);
  EXPECT_NEAR(o.extinctionAt550PerKm, 0.1746, 0.0002);
  EXPECT_NEAR(o.singleScatteringAlbedo, 0.8925, 0.0005);
  EXPECT_NEAR(o.asymmetry, 0.6977, 0.002);
  // OPAC's visibility is Koschmieder's at a 5% contrast threshold, 3.0 (ln 20) over the
  // aerosol's and the molecules' extinction (0.0116 /km at 550 nm); skyig's 3.912 is the 2% one.
  EXPECT_NEAR(3.0 / (o.extinctionAt550PerKm + 0.0116), 16.12, 0.05);
}

// The generated table's order is the enum's: every type carries its own OPAC name.
TEST(AerosolType, NamesRoundTripInTheTablesOrder) {
  EXPECT_EQ(parseAerosolType("bruneton2017"), AerosolType::bruneton2017);
  const char* names[] = {"continental_clean", "continental_average", "continental_polluted", "urban",
                         "desert", "maritime_clean", "maritime_polluted", "maritime_tropical", "arctic", "antarctic"};
  for (std::size_t i = 0; i < std::size(kOpacTypes); ++i) {
    EXPECT_EQ(aerosolTypeName(kOpacTypes[i]), names[i]);
    EXPECT_EQ(parseAerosolType(names[i]), kOpacTypes[i]) << names[i];
  }
  EXPECT_FALSE(parseAerosolType("continental"));
  EXPECT_NE(aerosolTypeNames().find("desert"), std::string_view::npos);
}

// Every table, at every OPAC humidity class and between them, is a phase function: the
// interpolant the shaders evaluate integrates to 1 over the sphere, and its mean cosine is the
// asymmetry parameter OPAC computed from its own 167 angles.
TEST(AerosolType, TabulatedPhaseFunctionsIntegrateToOneWithOpacsAsymmetry) {
  for (AerosolType t : kOpacTypes) {
    for (double rh : {0.0, 0.5, 0.65, 0.8, 0.97, 0.99}) {
      const AtmosphereParameters atm = parametersOf(t, rh);
      double norm = 0.0, mean = 0.0;
      constexpr int kSteps = 200000;
      for (int i = 0; i < kSteps; ++i) {  // midpoint rule in u = sqrt(theta / pi)
        const double u = (i + 0.5) / kSteps;
        const double theta = kPi * u * u;
        const double w = 2.0 * kPi * std::sin(theta) * 2.0 * kPi * u / kSteps;
        const double p = shader::tabulatedPhaseFunction(atm, std::cos(theta));
        norm += p * w;
        mean += p * std::cos(theta) * w;
      }
      EXPECT_NEAR(norm, 1.0, 1e-3) << aerosolTypeName(t) << " at " << rh;
      EXPECT_NEAR(mean, aerosolOptics(t, rh).asymmetry, 0.01) << aerosolTypeName(t) << " at " << rh;
    }
  }
}

// A real aerosol's forward peak: Mie scattering by OPAC's size distributions is, a degree from
// the sun, several times what a Cornette-Shanks function of the same asymmetry gives (2.4-8.5
// times at 50%), less from 5 to 30 degrees, and a third more at 90: the aureole the one-lobe
// function could not make.
TEST(AerosolType, ForwardPeakIsSeveralTimesOneLobesOfTheSameAsymmetry) {
  for (AerosolType t : {AerosolType::continentalClean, AerosolType::maritimeClean, AerosolType::desert}) {
    const AtmosphereParameters atm = parametersOf(t, 0.5);
    const double g = aerosolOptics(t, 0.5).asymmetry;
    const double at1 = std::cos(1.0 * kDegree);
    EXPECT_GT(shader::miePhaseFunction(atm, at1), 2.0 * shader::cornetteShanksPhaseFunction(g, at1)) << aerosolTypeName(t);
    const double at10 = std::cos(10.0 * kDegree);
    EXPECT_LT(shader::miePhaseFunction(atm, at10), shader::cornetteShanksPhaseFunction(g, at10)) << aerosolTypeName(t);
    EXPECT_GT(shader::miePhaseFunction(atm, 0.0), 1.1 * shader::cornetteShanksPhaseFunction(g, 0.0)) << aerosolTypeName(t);
  }
  // Bruneton's aerosol stays Cornette-Shanks with the medium's g.
  const AtmosphereParameters bruneton = makeParameters(Medium{}, {440.0, 550.0, 680.0, 830.0}, TableSizes::small());
  EXPECT_EQ(bruneton.mie_phase_tabulated, 0.0);
  EXPECT_DOUBLE_EQ(shader::miePhaseFunction(bruneton, 0.3), shader::cornetteShanksPhaseFunction(0.8, 0.3));
}

// Water makes the particles grow (Hanel 1976): OPAC's extinction and albedo rise with humidity
// for the hygroscopic types, and the desert's mineral dust hardly changes.
TEST(AerosolType, HygroscopicGrowthRaisesExtinctionAndAlbedo) {
  for (AerosolType t : kOpacTypes) {
    double ext = 0.0, albedo = 0.0;
    for (double rh : kOpacHumidityClasses) {
      const AerosolOptics o = aerosolOptics(t, rh);
      EXPECT_GT(o.extinctionAt550PerKm, ext) << aerosolTypeName(t) << " at " << rh;
      EXPECT_GE(o.singleScatteringAlbedo, albedo) << aerosolTypeName(t) << " at " << rh;
      ext = o.extinctionAt550PerKm;
      albedo = o.singleScatteringAlbedo;
    }
  }
  const double continental = aerosolOptics(AerosolType::continentalAverage, 0.95).extinctionAt550PerKm /
                             aerosolOptics(AerosolType::continentalAverage, 0.5).extinctionAt550PerKm;
  const double desert = aerosolOptics(AerosolType::desert, 0.95).extinctionAt550PerKm /
                        aerosolOptics(AerosolType::desert, 0.5).extinctionAt550PerKm;
  EXPECT_GT(continental, 2.5);
  EXPECT_LT(desert, 1.3);
  // Fine particles are blue (Angstrom exponent above 1), sea salt and dust nearly grey.
  EXPECT_GT(aerosolOptics(AerosolType::urban, 0.5).angstromExponent, 1.0);
  EXPECT_LT(aerosolOptics(AerosolType::maritimeClean, 0.5).angstromExponent, 0.5);
  EXPECT_LT(aerosolOptics(AerosolType::desert, 0.5).angstromExponent, 0.5);
  EXPECT_THROW(aerosolOptics(AerosolType::urban, 1.0), std::invalid_argument);
  EXPECT_THROW(aerosolOptics(AerosolType::bruneton2017, 0.5), std::invalid_argument);
}

// The host's humidity makes the configured particles what OPAC has them at its nearest class;
// without a visibility their extinction grows as OPAC's; a visibility sets the amount and keeps
// the type's albedo (its water is the humidity's, not the amount's).
TEST(AerosolType, HostHumiditySetsTheParticlesAndVisibilityTheirAmount) {
  const Medium base = withAerosolType(Medium{}, AerosolType::continentalAverage, 0.5);
  Conditions humid;
  humid.relativeHumidity = 0.88;
  const Medium grown = applyConditions(base, humid);
  EXPECT_EQ(grown.aerosolHumidity, 0.9);
  const AerosolOptics at90 = aerosolOptics(AerosolType::continentalAverage, 0.9);
  EXPECT_DOUBLE_EQ(grown.mieSingleScatteringAlbedo, at90.singleScatteringAlbedo);
  EXPECT_NEAR(grown.mieExtinctionPerM / base.mieExtinctionPerM,
              at90.extinctionAt550PerKm / aerosolOptics(AerosolType::continentalAverage, 0.5).extinctionAt550PerKm,
              1e-12);
  humid.visibilityKm = 20.0;
  const Medium hazy = applyConditions(base, humid);
  EXPECT_NEAR(visibilityOf(hazy), 20.0, 1e-9);
  EXPECT_DOUBLE_EQ(hazy.mieSingleScatteringAlbedo, at90.singleScatteringAlbedo);
  // Bruneton's aerosol: the humidity still only scales its amount (Hanel's law), and a visibility
  // with more aerosol raises its albedo as water would.
  Conditions thick;
  thick.visibilityKm = 20.0;
  EXPECT_GT(applyConditions(Medium{}, thick).mieSingleScatteringAlbedo, 0.99);
}

// Bodhaine et al. 1999, eq. 30: the Rayleigh optical depth at sea level; skyig's molecules with
// kBodhaineRayleighScatteringAt1umPerM over their 8 km scale height within 2.5% of it from
// blue to red (the lambda^-4 law against Bodhaine's steeper one, about lambda^-4.08).
TEST(RayleighScattering, BodhainesOpticalDepthFromBlueToRed) {
  auto bodhaine = [](double um) {
    const double l2 = um * um;
    return 0.0021520 * (1.0455996 - 341.29061 / l2 - 0.90230850 * l2) / (1.0 + 0.0027059889 / l2 - 85.968563 * l2);
  };
  Medium m;
  m.rayleighScatteringAt1umPerM = kBodhaineRayleighScatteringAt1umPerM;
  for (double nm : {440.0, 500.0, 550.0, 600.0, 680.0}) {
    const double tau = coefficientsAt(m, nm).rayleighScattering * m.rayleighScaleHeightM;
    EXPECT_NEAR(tau / bodhaine(nm * 1e-3), 1.0, nm == 550.0 ? 0.001 : 0.025) << nm << " nm";
  }
  EXPECT_NEAR(bodhaine(0.55), 0.0971, 0.0001);
  // Bruneton's default molecules are 11.7% above it at 550 nm.
  EXPECT_NEAR(coefficientsAt(Medium{}, 550.0).rayleighScattering * 8000.0 / bodhaine(0.55), 1.117, 0.003);
}

}  // namespace
}  // namespace skyig::atmosphere
