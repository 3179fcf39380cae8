#pragma once
// The CIGI Celestial Sphere Control date: one 32-bit integer whose decimal digits are
// MMDDYYYY (ICD 3.3, Celestial Sphere Control "Date"), e.g. 21 June 2026 is 6212026.
#include <cstdint>
#include <optional>
#include <string>

namespace skyig::protocol::cigi {

struct CivilDate {
  int year = 2000;
  int month = 1;
  int day = 1;
  bool operator==(const CivilDate&) const = default;
};

// Splits MMDDYYYY; nullopt when the month is not 1..12 or the day is not in that month
// (Gregorian leap years).
std::optional<CivilDate> splitDate(std::uint32_t mmddyyyy);

// Composes MMDDYYYY; nullopt when the date is invalid or the year is outside 0..9999.
std::optional<std::uint32_t> composeDate(const CivilDate& d);

// "2026-06-21"
std::string formatDate(const CivilDate& d);

}  // namespace skyig::protocol::cigi
