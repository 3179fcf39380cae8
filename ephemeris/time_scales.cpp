#include "ephemeris/time_scales.h"

#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>

namespace skyig::ephemeris {

namespace {
// TAI - UTC since 1972 (IERS Bulletin C; the list in SOFA/ERFA dat.c and IERS Leap_Second.dat).
// To update: when IERS Bulletin C announces a leap second, append {year, month, new TAI-UTC}
// here (the step happens at 0h UTC on the first day of that month) and extend the test.
struct LeapStep {
  int year, month;
  double taiMinusUtc;
};
constexpr LeapStep kLeapSeconds[] = {
    {1972, 1, 10}, {1972, 7, 11}, {1973, 1, 12}, {1974, 1, 13}, {1975, 1, 14}, {1976, 1, 15},
    {1977, 1, 16}, {1978, 1, 17}, {1979, 1, 18}, {1980, 1, 19}, {1981, 7, 20}, {1982, 7, 21},
    {1983, 7, 22}, {1985, 7, 23}, {1988, 1, 24}, {1990, 1, 25}, {1991, 1, 26}, {1992, 7, 27},
    {1993, 7, 28}, {1994, 7, 29}, {1996, 1, 30}, {1997, 7, 31}, {1999, 1, 32}, {2006, 1, 33},
    {2009, 1, 34}, {2012, 7, 35}, {2015, 7, 36}, {2017, 1, 37},
};
}  // namespace

std::optional<double> taiMinusUtc(double jdUtc) {
  if (jdUtc < julianDayAt0h(1972, 1, 1)) return std::nullopt;
  double value = kLeapSeconds[0].taiMinusUtc;
  for (const LeapStep& s : kLeapSeconds)
    if (jdUtc >= julianDayAt0h(s.year, s.month, 1)) value = s.taiMinusUtc;
  return value;
}

double lastLeapSecondJd() {
  const LeapStep& s = kLeapSeconds[std::size(kLeapSeconds) - 1];
  return julianDayAt0h(s.year, s.month, 1);
}

double deltaTPolynomial(double y) {
  // Espenak & Meeus (2006), valid 1900-2150.
  if (y < 1920.0) {
    const double t = y - 1900.0;
    return -2.79 + t * (1.494119 + t * (-0.0598939 + t * (0.0061966 - 0.000197 * t)));
  }
  if (y < 1941.0) {
    const double t = y - 1920.0;
    return 21.20 + t * (0.84493 + t * (-0.076100 + 0.0020936 * t));
  }
  if (y < 1961.0) {
    const double t = y - 1950.0;
    return 29.07 + 0.407 * t - t * t / 233.0 + t * t * t / 2547.0;
  }
  if (y < 1986.0) {
    const double t = y - 1975.0;
    return 45.45 + 1.067 * t - t * t / 260.0 - t * t * t / 718.0;
  }
  if (y < 2005.0) {
    const double t = y - 2000.0;
    return 63.86 + t * (0.3345 + t * (-0.060374 + t * (0.0017275 + t * (0.000651814 + 0.00002373599 * t))));
  }
  if (y < 2050.0) {
    const double t = y - 2000.0;
    return 62.92 + t * (0.32217 + 0.005589 * t);
  }
  const double u = (y - 1820.0) / 100.0;
  return -20.0 + 32.0 * u * u - 0.5628 * (2150.0 - y);
}

TimeScales timeScales(const UtcTime& utc, std::optional<double> ttMinusUtcS,
                      std::optional<double> dut1S) {
  if (const std::string err = validate(utc); !err.empty())
    throw std::invalid_argument("invalid UTC time: " + err);
  if (utc.year < kFirstSupportedYear || utc.year > kLastSupportedYear)
    throw std::invalid_argument("year " + std::to_string(utc.year) + " is outside the supported " +
                                std::to_string(kFirstSupportedYear) + "-" +
                                std::to_string(kLastSupportedYear) + " range of the ephemeris");
  if (ttMinusUtcS && !(std::isfinite(*ttMinusUtcS) && std::fabs(*ttMinusUtcS) < 1000.0))
    throw std::invalid_argument("TT - UTC of " + std::to_string(*ttMinusUtcS) +
                                " s is not a finite value within +-1000 s");
  if (dut1S && !(std::isfinite(*dut1S) && std::fabs(*dut1S) < 1000.0))
    throw std::invalid_argument("DUT1 of " + std::to_string(*dut1S) +
                                " s is not a finite value within +-1000 s");
  TimeScales ts;
  ts.jdUtc = julianDateUtc(utc);
  ts.ut1MinusUtcS = dut1S.value_or(0.0);
  if (ttMinusUtcS) {
    ts.ttMinusUtcS = *ttMinusUtcS;
  } else if (const auto leap = taiMinusUtc(ts.jdUtc); leap) {
    ts.ttMinusUtcS = 32.184 + *leap;
  } else {
    const double year = utc.year + (utc.month - 0.5) / 12.0;
    ts.ttMinusUtcS = deltaTPolynomial(year) + ts.ut1MinusUtcS;
  }
  ts.jdTt = ts.jdUtc + ts.ttMinusUtcS / 86400.0;
  ts.jdUt1 = ts.jdUtc + ts.ut1MinusUtcS / 86400.0;
  return ts;
}

}  // namespace skyig::ephemeris
