// A full ephemeris update as the worker thread does it every frame (sun, moon, five planets with
// topocentric azimuth/altitude, moon appearance, magnitudes, the star matrix), side by side with
// Swiss Ephemeris doing the same work, 60 frames a second of simulated time.
// Run: build/tests/ephemeris/ephemeris_bench --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include "ephemeris/ephemeris.h"
#include "ephemeris/ephemeris_cache.h"
#include "ephemeris/series_state.h"

#if SKYIG_HAVE_REFERENCE_LIBS
#include <swephexp.h>
#endif

using namespace skyig::ephemeris;

namespace {
constexpr double kLatDeg = 46.2, kLonDeg = 7.3, kHeightM = 600.0;

Observer observer() {
  Observer o;
  o.latitudeRad = kLatDeg * kDegToRad;
  o.longitudeRad = kLonDeg * kDegToRad;
  o.heightM = kHeightM;
  return o;
}

void BM_Skyig_FullUpdate(benchmark::State& state) {
  const Observer o = observer();
  UtcTime t{2030, 5, 17, 0.0};
  for (auto _ : state) {
    t.secondsOfDay += 1.0 / 60.0;
    if (t.secondsOfDay >= 86400.0) t.secondsOfDay = 0.0;
    benchmark::DoNotOptimize(computeEphemeris(t, o));
  }
}
BENCHMARK(BM_Skyig_FullUpdate);

void BM_Skyig_FullUpdateCached(benchmark::State& state) {
  const Observer o = observer();
  EphemerisCache cache;
  UtcTime t{2030, 5, 17, 0.0};
  for (auto _ : state) {
    t.secondsOfDay += 1.0 / 60.0;
    if (t.secondsOfDay >= 86400.0) t.secondsOfDay = 0.0;
    benchmark::DoNotOptimize(cache.compute(t, o));
  }
  state.counters["series_evaluations"] = static_cast<double>(cache.evaluations());
}
BENCHMARK(BM_Skyig_FullUpdateCached);

void BM_Skyig_SeriesOnly(benchmark::State& state) {
  double jd = 2462638.5;
  for (auto _ : state) {
    jd += 1.0 / 86400.0 / 60.0;
    benchmark::DoNotOptimize(evaluateSeries(jd));
  }
}
BENCHMARK(BM_Skyig_SeriesOnly);

#if SKYIG_HAVE_REFERENCE_LIBS
void sweFrame(double jdUt, bool withPhenomena, benchmark::State& state) {
  static const int kBodies[7] = {SE_SUN, SE_MOON, SE_MERCURY, SE_VENUS, SE_MARS, SE_JUPITER, SE_SATURN};
  double geopos[3] = {kLonDeg, kLatDeg, kHeightM};
  char err[AS_MAXCH];
  for (int b : kBodies) {
    double xx[6], hor[3];
    if (swe_calc_ut(jdUt, b, SEFLG_SWIEPH | SEFLG_TOPOCTR | SEFLG_EQUATORIAL, xx, err) < 0) state.SkipWithError(err);
    swe_azalt(jdUt, SE_EQU2HOR, geopos, 1010.0, 10.0, xx, hor);
    benchmark::DoNotOptimize(hor);
    if (withPhenomena && b != SE_SUN) {  // moon phase and planet magnitudes
      double attr[20];
      swe_pheno_ut(jdUt, b, SEFLG_SWIEPH | SEFLG_TOPOCTR, attr, err);
      benchmark::DoNotOptimize(attr);
    }
  }
  benchmark::DoNotOptimize(swe_sidtime(jdUt));
}

void BM_SwissEphemeris_FullUpdate(benchmark::State& state) {
  swe_set_ephe_path(const_cast<char*>("/usr/share/libswe/ephe"));
  swe_set_topo(kLonDeg, kLatDeg, kHeightM);
  double jd = 2462638.5;
  for (auto _ : state) {
    jd += 1.0 / 86400.0 / 60.0;
    sweFrame(jd, true, state);
  }
}
BENCHMARK(BM_SwissEphemeris_FullUpdate);

void BM_SwissEphemeris_PositionsOnly(benchmark::State& state) {
  swe_set_ephe_path(const_cast<char*>("/usr/share/libswe/ephe"));
  swe_set_topo(kLonDeg, kLatDeg, kHeightM);
  double jd = 2462638.5;
  for (auto _ : state) {
    jd += 1.0 / 86400.0 / 60.0;
    sweFrame(jd, false, state);
  }
}
BENCHMARK(BM_SwissEphemeris_PositionsOnly);
#endif
}  // namespace

BENCHMARK_MAIN();
