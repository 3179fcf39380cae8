#include "protocol/canaerospace/state_decoder.h"

#include <bit>
#include <cmath>
#include <cstdio>

namespace skyig::protocol::canaerospace {

namespace {

std::string idText(const Message& m) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "id %u ($%X), %s", static_cast<unsigned>(m.id), static_cast<unsigned>(m.id),
                dataTypeName(m.dataType));
  return buf;
}

FeedResult fail(FeedStatus s, std::string detail) { return FeedResult{s, std::move(detail)}; }

bool leap(int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }
int daysIn(int y, int m) {
  constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return m == 2 && leap(y) ? 29 : kDays[m - 1];
}

}  // namespace

const char* toString(FeedStatus s) {
  switch (s) {
    case FeedStatus::applied: return "applied";
    case FeedStatus::pendingHalf: return "DOUBLEH waiting for DOUBLEL";
    case FeedStatus::ignored: return "identifier not mapped";
    case FeedStatus::malformedFrame: return "malformed frame";
    case FeedStatus::wrongDataType: return "wrong data type";
    case FeedStatus::badValue: return "bad value";
    case FeedStatus::unpairedHalf: return "DOUBLEL without DOUBLEH";
  }
  return "unknown";
}

FeedResult StateDecoder::feed(const CanFrame& frame) {
  Message m;
  FeedResult r;
  const FrameError e = parseFrame(frame, m);
  if (e != FrameError::none) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "CAN id 0x%X, DLC %u: ", static_cast<unsigned>(frame.identifier()),
                  static_cast<unsigned>(frame.len));
    r = fail(FeedStatus::malformedFrame, buf + std::string(toString(e)));
  } else {
    r = feedMessage(m);
  }
  ++counts_[static_cast<std::size_t>(r.status)];
  return r;
}

FeedResult StateDecoder::angleOrLength(const Message& m, double& target, std::uint32_t field, double lo, double hi) {
  if (m.dataType != static_cast<std::uint8_t>(DataType::floatType))
    return fail(FeedStatus::wrongDataType, idText(m) + ": expected FLOAT");
  const double v = static_cast<double>(m.asFloat());
  if (!std::isfinite(v) || v < lo || v > hi)
    return fail(FeedStatus::badValue, idText(m) + ": value " + std::to_string(v) + " outside [" +
                                          std::to_string(lo) + ", " + std::to_string(hi) + "]");
  target = v;
  state_.seen |= field;
  return {};
}

FeedResult StateDecoder::latLon(const Message& m, PendingHalf& pending, double& target, std::uint32_t field,
                                double limit) {
  double v = 0.0;
  switch (static_cast<DataType>(m.dataType)) {
    case DataType::floatType: v = static_cast<double>(m.asFloat()); pending.valid = false; break;
    case DataType::doubleH:
      // The spec does not say how halves pair; skyig reads them as two messages on the same
      // id, DOUBLEH then DOUBLEL, with consecutive message codes (docs/protocol.md).
      pending = PendingHalf{true, m.u32(), m.messageCode};
      return FeedResult{FeedStatus::pendingHalf, {}};
    case DataType::doubleL: {
      const bool paired = pending.valid && static_cast<std::uint8_t>(pending.messageCode + 1) == m.messageCode;
      const PendingHalf high = pending;
      pending.valid = false;
      if (!paired)
        return fail(FeedStatus::unpairedHalf,
                    idText(m) + ": message code " + std::to_string(m.messageCode) +
                        (high.valid ? " does not follow DOUBLEH code " + std::to_string(high.messageCode)
                                    : " with no DOUBLEH before it"));
      v = std::bit_cast<double>((static_cast<std::uint64_t>(high.high) << 32) | m.u32());
      break;
    }
    case DataType::longType:
      if (map_.acceptLongLatLon1e7) {
        v = m.asLong() * 1e-7;
        pending.valid = false;
        break;
      }
      [[fallthrough]];
    default: return fail(FeedStatus::wrongDataType, idText(m) + ": expected FLOAT or DOUBLEH+DOUBLEL");
  }
  if (!std::isfinite(v) || std::abs(v) > limit)
    return fail(FeedStatus::badValue, idText(m) + ": value " + std::to_string(v) + " outside [-" +
                                          std::to_string(limit) + ", " + std::to_string(limit) + "]");
  target = v;
  state_.seen |= field;
  return {};
}

FeedResult StateDecoder::feedMessage(const Message& m) {
  if (map_.nodeId >= 0 && m.nodeId != map_.nodeId) return FeedResult{FeedStatus::ignored, {}};
  if (m.id == map_.latitude) return latLon(m, latPending_, state_.latitudeDeg, kLatitude, 90.0);
  if (m.id == map_.longitude) return latLon(m, lonPending_, state_.longitudeDeg, kLongitude, 180.0);
  if (m.id == map_.altitude) return angleOrLength(m, state_.altitudeM, kAltitude, -1.0e5, 1.0e6);
  if (m.id == map_.bodyPitch) return angleOrLength(m, state_.pitchDeg, kPitch, -90.0, 90.0);
  if (m.id == map_.bodyRoll) return angleOrLength(m, state_.rollDeg, kRoll, -180.0, 180.0);
  if (m.id == map_.heading) {
    // CANaerospace heading is +-180 deg (spec section 5); CIGI yaw and skyig use 0..360.
    double h = 0.0;
    FeedResult r = angleOrLength(m, h, kHeading, -180.0, 360.0);
    if (r.ok()) state_.headingDeg = h < 0.0 ? h + 360.0 : h;
    return r;
  }
  if (m.id == map_.utc || m.id == map_.date) {
    if (m.dataType != static_cast<std::uint8_t>(DataType::char4) &&
        m.dataType != static_cast<std::uint8_t>(DataType::uchar4))
      return fail(FeedStatus::wrongDataType, idText(m) + ": expected CHAR4");
    const int a = m.data[0], b = m.data[1], c = m.data[2], d = m.data[3];
    if (m.id == map_.utc) {
      // UTC: hh mm ss 00 (spec section 5, id 1200).
      if (a > 23 || b > 59 || c > 60)
        return fail(FeedStatus::badValue, idText(m) + ": time " + std::to_string(a) + ":" + std::to_string(b) +
                                              ":" + std::to_string(c) + " out of range");
      state_.hour = a;
      state_.minute = b;
      state_.second = c;
      state_.seen |= kUtcTime;
    } else {
      // Date: dd mm cc yy (spec section 5, id 1206): 12 June 1987 = 0C 06 13 57.
      const int year = c * 100 + d;
      if (b < 1 || b > 12 || c > 99 || d > 99 || a < 1 || a > daysIn(year, b))
        return fail(FeedStatus::badValue, idText(m) + ": date day " + std::to_string(a) + " month " +
                                              std::to_string(b) + " year " + std::to_string(year) + " invalid");
      state_.day = a;
      state_.month = b;
      state_.year = year;
      state_.seen |= kDate;
    }
    return {};
  }
  return FeedResult{FeedStatus::ignored, {}};
}

}  // namespace skyig::protocol::canaerospace
