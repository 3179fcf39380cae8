// Time scales against the IERS leap-second history and published delta T values.
#include "ephemeris/time_scales.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace skyig::ephemeris;

TEST(TimeScales, LeapSecondTableSteps) {
  // IERS Bulletin C: TAI-UTC = 10 s from 1972-01-01, 36 s on 2016-12-31, 37 s from 2017-01-01.
  EXPECT_EQ(*taiMinusUtc(julianDayAt0h(1972, 1, 1)), 10.0);
  EXPECT_EQ(*taiMinusUtc(julianDayAt0h(1972, 6, 30) + 0.99), 10.0);
  EXPECT_EQ(*taiMinusUtc(julianDayAt0h(1972, 7, 1)), 11.0);
  EXPECT_EQ(*taiMinusUtc(julianDayAt0h(2016, 12, 31) + 0.5), 36.0);
  EXPECT_EQ(*taiMinusUtc(julianDayAt0h(2017, 1, 1)), 37.0);
  EXPECT_EQ(*taiMinusUtc(julianDayAt0h(2099, 1, 1)), 37.0);  // no future leap second known
  EXPECT_FALSE(taiMinusUtc(julianDayAt0h(1971, 12, 31)).has_value());
  EXPECT_EQ(lastLeapSecondJd(), julianDayAt0h(2017, 1, 1));
}

TEST(TimeScales, TtMinusUtcInTheLeapSecondEra) {
  const TimeScales ts = timeScales(UtcTime{2020, 3, 1, 43200.0});
  EXPECT_DOUBLE_EQ(ts.ttMinusUtcS, 69.184);  // 32.184 + 37
  EXPECT_NEAR((ts.jdTt - ts.jdUtc) * 86400.0, 69.184, 1e-4);
  EXPECT_DOUBLE_EQ(ts.ut1MinusUtcS, 0.0);
}

TEST(TimeScales, DeltaTPolynomialMatchesObservedValues) {
  // Observed delta T (IERS / Astronomical Almanac): 1900.0 -2.7 s, 1950.0 29.15 s, 1975.0 45.48 s,
  // 2000.0 63.83 s; the polynomials fit them to within about 0.5 s. (Their 2005-2050 piece is a
  // 2006 prediction, 0.6 s high by 2010; skyig uses the leap-second table from 1972 on.)
  EXPECT_NEAR(deltaTPolynomial(1900.0), -2.72, 0.5);
  EXPECT_NEAR(deltaTPolynomial(1950.0), 29.15, 0.5);
  EXPECT_NEAR(deltaTPolynomial(1975.0), 45.48, 0.5);
  EXPECT_NEAR(deltaTPolynomial(2000.0), 63.83, 0.5);
  // Continuity at the joins of the pieces (within 0.1 s).
  for (double y : {1920.0, 1941.0, 1961.0, 1986.0, 2005.0, 2050.0})
    EXPECT_NEAR(deltaTPolynomial(y - 1e-9), deltaTPolynomial(y), 0.1) << y;
}

TEST(TimeScales, BeforeTheLeapSecondEraDeltaTPlusDut1) {
  const TimeScales ts = timeScales(UtcTime{1950, 1, 1, 0.0}, std::nullopt, 0.25);
  EXPECT_NEAR(ts.ttMinusUtcS, deltaTPolynomial(1950.0 + 0.5 / 12.0) + 0.25, 1e-9);
  EXPECT_NEAR((ts.jdUt1 - ts.jdUtc) * 86400.0, 0.25, 1e-5);
}

TEST(TimeScales, OverridesAreUsed) {
  const TimeScales ts = timeScales(UtcTime{2000, 1, 1, 0.0}, 64.0, -0.3);
  EXPECT_DOUBLE_EQ(ts.ttMinusUtcS, 64.0);
  EXPECT_DOUBLE_EQ(ts.ut1MinusUtcS, -0.3);
}

TEST(TimeScales, RejectsDatesOutsideTheSupportedRange) {
  EXPECT_THROW(timeScales(UtcTime{1899, 12, 31, 0.0}), std::invalid_argument);
  EXPECT_THROW(timeScales(UtcTime{2101, 1, 1, 0.0}), std::invalid_argument);
  EXPECT_THROW(timeScales(UtcTime{2021, 2, 29, 0.0}), std::invalid_argument);
  EXPECT_THROW(timeScales(UtcTime{2021, 1, 1, 0.0}, std::nan("")), std::invalid_argument);
  try {
    timeScales(UtcTime{2101, 1, 1, 0.0});
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("2101"), std::string::npos) << e.what();
  }
}
