#include "ephemeris/time.h"

#include <cmath>
#include <cstdio>

namespace skyig::ephemeris {

namespace {
bool isLeapYear(int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

int daysInMonth(int y, int m) {
  static constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return m == 2 && isLeapYear(y) ? 29 : kDays[m - 1];
}
}  // namespace

double julianDayAt0h(int year, int month, int day) {
  // Meeus eq. 7.1, Gregorian calendar (B = 2 - A + A/4).
  if (month <= 2) {
    year -= 1;
    month += 12;
  }
  const int a = year / 100;
  const int b = 2 - a + a / 4;
  return std::floor(365.25 * (year + 4716)) + std::floor(30.6001 * (month + 1)) + day + b - 1524.5;
}

double julianDateUtc(const UtcTime& t) {
  return julianDayAt0h(t.year, t.month, t.day) + t.secondsOfDay / 86400.0;
}

std::string validate(const UtcTime& t) {
  char buf[128];
  if (t.month < 1 || t.month > 12) {
    std::snprintf(buf, sizeof buf, "month %d is outside 1-12", t.month);
    return buf;
  }
  if (t.day < 1 || t.day > daysInMonth(t.year, t.month)) {
    std::snprintf(buf, sizeof buf, "day %d is outside 1-%d for %04d-%02d", t.day,
                  daysInMonth(t.year, t.month), t.year, t.month);
    return buf;
  }
  if (!(t.secondsOfDay >= 0.0 && t.secondsOfDay < 86401.0)) {
    std::snprintf(buf, sizeof buf, "time of day %g s is outside [0, 86401)", t.secondsOfDay);
    return buf;
  }
  return {};
}

std::optional<UtcTime> parseIso8601Utc(std::string_view text) {
  const std::string s(text);
  int y = 0, mo = 0, d = 0, h = 0, mi = 0, consumed = 0;
  double sec = 0.0;
  if (std::sscanf(s.c_str(), "%4d-%2d-%2dT%2d:%2d:%lf%n", &y, &mo, &d, &h, &mi, &sec, &consumed) != 6)
    return std::nullopt;
  const std::string_view rest = text.substr(static_cast<size_t>(consumed));
  if (!(rest.empty() || rest == "Z" || rest == "z" || rest == "+00:00")) return std::nullopt;
  if (h < 0 || h > 23 || mi < 0 || mi > 59 || !(sec >= 0.0 && sec < 61.0)) return std::nullopt;
  UtcTime t{y, mo, d, h * 3600.0 + mi * 60.0 + sec};
  if (!validate(t).empty()) return std::nullopt;
  return t;
}

std::string formatIso8601Utc(const UtcTime& t) {
  const long long ms = std::llround(t.secondsOfDay * 1000.0);
  const long long h = ms / 3600000, mi = (ms / 60000) % 60, s = (ms / 1000) % 60, frac = ms % 1000;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02lld:%02lld:%02lld.%03lldZ", t.year, t.month,
                t.day, h, mi, s, frac);
  return buf;
}

}  // namespace skyig::ephemeris
