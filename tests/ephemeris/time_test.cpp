#include "ephemeris/time.h"

#include <gtest/gtest.h>

using namespace skyig::ephemeris;

// Meeus, Astronomical Algorithms, example 7.a: 1957 October 4.81 = JD 2436116.31.
TEST(JulianDate, MeeusExample7a) {
  EXPECT_NEAR(julianDateUtc({1957, 10, 4, 0.81 * 86400.0}), 2436116.31, 1e-9);
}

// Meeus p. 62 table: 2000 Jan 1.5 = 2451545.0, 1987 June 19.5 = 2446966.0, 1600 Dec 31 = 2305812.5.
TEST(JulianDate, MeeusTable) {
  EXPECT_DOUBLE_EQ(julianDateUtc({2000, 1, 1, 43200.0}), 2451545.0);
  EXPECT_DOUBLE_EQ(julianDateUtc({1987, 6, 19, 43200.0}), 2446966.0);
  EXPECT_DOUBLE_EQ(julianDateUtc({1600, 12, 31, 0.0}), 2305812.5);
}

TEST(Iso8601, ParsesAndFormats) {
  const auto t = parseIso8601Utc("2026-06-21T19:30:15.250Z");
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(t->year, 2026);
  EXPECT_EQ(t->month, 6);
  EXPECT_EQ(t->day, 21);
  EXPECT_DOUBLE_EQ(t->secondsOfDay, 19 * 3600 + 30 * 60 + 15.25);
  EXPECT_EQ(formatIso8601Utc(*t), "2026-06-21T19:30:15.250Z");
}

TEST(Iso8601, RejectsBadFields) {
  EXPECT_FALSE(parseIso8601Utc("2026-02-30T00:00:00Z"));  // no 30 February
  EXPECT_FALSE(parseIso8601Utc("2026-13-01T00:00:00Z"));
  EXPECT_FALSE(parseIso8601Utc("2026-06-21T24:00:00Z"));
  EXPECT_FALSE(parseIso8601Utc("2026-06-21T12:00:00+02:00"));  // UTC only
  EXPECT_FALSE(parseIso8601Utc("yesterday"));
  EXPECT_TRUE(parseIso8601Utc("2024-02-29T00:00:00"));  // leap year
}
