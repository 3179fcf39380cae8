#pragma once
// Civil time to Julian dates. Angles in radians inside skyig, degrees at interfaces.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace skyig::ephemeris {

// A UTC instant as the host sends it: calendar date and seconds of the day.
struct UtcTime {
  int year = 2000;
  int month = 1;
  int day = 1;
  double secondsOfDay = 0.0;  // [0, 86400] (86400.x only inside a leap second)
};

// Julian date of a Gregorian calendar date at 0h (Meeus, Astronomical Algorithms, eq. 7.1).
double julianDayAt0h(int year, int month, int day);

// Julian date (UTC based) of an instant.
double julianDateUtc(const UtcTime& t);

// Parses "YYYY-MM-DDTHH:MM:SS[.fff][Z]"; nullopt when the text or a field is invalid.
std::optional<UtcTime> parseIso8601Utc(std::string_view text);

// "YYYY-MM-DDTHH:MM:SS.mmmZ"
std::string formatIso8601Utc(const UtcTime& t);

// Checks ranges (month 1-12, day within the month, seconds in [0, 86401)); a message naming
// the bad field, or empty when valid.
std::string validate(const UtcTime& t);

}  // namespace skyig::ephemeris
