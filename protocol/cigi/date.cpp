#include "protocol/cigi/date.h"

#include <cstdio>

namespace skyig::protocol::cigi {

namespace {

bool isLeap(int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

int daysInMonth(int y, int m) {
  constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return m == 2 && isLeap(y) ? 29 : kDays[m - 1];
}

bool valid(const CivilDate& d) {
  return d.year >= 0 && d.year <= 9999 && d.month >= 1 && d.month <= 12 && d.day >= 1 &&
         d.day <= daysInMonth(d.year, d.month);
}

}  // namespace

std::optional<CivilDate> splitDate(std::uint32_t mmddyyyy) {
  const CivilDate d{static_cast<int>(mmddyyyy % 10000u), static_cast<int>(mmddyyyy / 1000000u),
                    static_cast<int>(mmddyyyy / 10000u % 100u)};
  if (!valid(d)) return std::nullopt;
  return d;
}

std::optional<std::uint32_t> composeDate(const CivilDate& d) {
  if (!valid(d)) return std::nullopt;
  return static_cast<std::uint32_t>(d.month) * 1000000u + static_cast<std::uint32_t>(d.day) * 10000u +
         static_cast<std::uint32_t>(d.year);
}

std::string formatDate(const CivilDate& d) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%04d-%02d-%02d", d.year, d.month, d.day);
  return buf;
}

}  // namespace skyig::protocol::cigi
