#pragma once
// Time scales: UTC -> TAI (leap-second table) -> TT, UT1 = UTC + DUT1, and delta T = TT - UT1
// outside the leap-second era (Espenak & Meeus polynomials, NASA "Five Millennium Canon of
// Solar Eclipses", 2006, section "Polynomial expressions for delta T").
#include <optional>

#include "ephemeris/time.h"

namespace skyig::ephemeris {

// Supported span of every ephemeris computation (the series are truncated for it).
inline constexpr int kFirstSupportedYear = 1900;
inline constexpr int kLastSupportedYear = 2100;

struct TimeScales {
  double jdUtc = 0.0;        // Julian date, UTC based
  double jdTt = 0.0;         // Terrestrial Time (used as TDB: |TDB - TT| < 2 ms)
  double jdUt1 = 0.0;        // UT1, the earth's rotation angle
  double ttMinusUtcS = 0.0;  // seconds
  double ut1MinusUtcS = 0.0; // seconds
};

// TAI - UTC in seconds from the leap-second table, or nullopt before 1972-01-01 (UTC was then
// not an integer offset from TAI). After the last table entry the last value is kept.
std::optional<double> taiMinusUtc(double jdUtc);

// Julian date (UTC) of the last leap-second entry in the table (to warn about stale tables).
double lastLeapSecondJd();

// Delta T = TT - UT1 in seconds (Espenak & Meeus 2006), decimal year y = year + (month - 0.5)/12.
double deltaTPolynomial(double decimalYear);

// All scales for a UTC instant. ttMinusUtcS and dut1S override the defaults: TT - UTC =
// 32.184 s + (TAI - UTC) from the table from 1972 on (its last value kept after its end: no
// future leap second is known), or delta T(year) + DUT1 before 1972; DUT1 = UT1 - UTC defaults to 0 (UTC is kept within 0.9 s of UT1).
// Throws std::invalid_argument for an invalid date or one outside 1900-2100.
TimeScales timeScales(const UtcTime& utc, std::optional<double> ttMinusUtcS = std::nullopt,
                      std::optional<double> dut1S = std::nullopt);

}  // namespace skyig::ephemeris
