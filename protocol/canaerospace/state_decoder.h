#pragma once
// Accumulates CANaerospace frames into the host state the IG needs: position, attitude,
// UTC date and time. Each parameter arrives in its own message at its own rate, so the
// state records which fields have been seen and when each was last updated (frame count).
#include <array>
#include <cstdint>
#include <string>

#include "protocol/canaerospace/can_frame.h"
#include "protocol/canaerospace/identifiers.h"
#include "protocol/canaerospace/message.h"

namespace skyig::protocol::canaerospace {

enum Field : std::uint32_t {
  kLatitude = 1u << 0,
  kLongitude = 1u << 1,
  kAltitude = 1u << 2,
  kHeading = 1u << 3,
  kPitch = 1u << 4,
  kRoll = 1u << 5,
  kUtcTime = 1u << 6,
  kDate = 1u << 7,
};

// The host's state as CANaerospace carries it (node/host/host_state.h's HostState, what the node
// renders from, is built from it and from CIGI).
struct CanAerospaceState {
  double latitudeDeg = 0.0;
  double longitudeDeg = 0.0;
  double altitudeM = 0.0;
  double headingDeg = 0.0;  // as CIGI yaw: true heading 0..360 (CANaerospace sends +-180)
  double pitchDeg = 0.0;
  double rollDeg = 0.0;
  int hour = 0, minute = 0, second = 0;  // UTC, whole seconds (CHAR4 hh mm ss)
  int year = 2000, month = 1, day = 1;
  std::uint32_t seen = 0;                // Field bits of the fields received at least once
  bool has(std::uint32_t fields) const { return (seen & fields) == fields; }
};

// What became of one frame. Stable values: they index counters.
enum class FeedStatus : std::uint8_t {
  applied = 0,     // a field of the state was updated
  pendingHalf,     // DOUBLEH stored, waiting for its DOUBLEL
  ignored,         // an identifier the map does not name
  malformedFrame,  // parseFrame failed (see the detail)
  wrongDataType,   // a mapped identifier with a data type skyig does not accept for it
  badValue,        // NaN, out of range, impossible time or date
  unpairedHalf,    // DOUBLEL without the DOUBLEH just before it (same id, message code - 1)
};
inline constexpr std::size_t kFeedStatusCount = 7;
const char* toString(FeedStatus s);

struct FeedResult {
  FeedStatus status = FeedStatus::applied;
  std::string detail;  // for errors: names the identifier and the offending value
  bool ok() const { return status == FeedStatus::applied || status == FeedStatus::pendingHalf ||
                           status == FeedStatus::ignored; }
};

class StateDecoder {
 public:
  explicit StateDecoder(IdentifierMap map = {}) : map_(map) {}

  FeedResult feed(const CanFrame& frame);
  const CanAerospaceState& state() const { return state_; }
  const IdentifierMap& map() const { return map_; }
  std::uint64_t count(FeedStatus s) const { return counts_[static_cast<std::size_t>(s)]; }

 private:
  struct PendingHalf {
    bool valid = false;
    std::uint32_t high = 0;
    std::uint8_t messageCode = 0;
  };
  FeedResult feedMessage(const Message& m);
  FeedResult angleOrLength(const Message& m, double& target, std::uint32_t field, double lo, double hi);
  FeedResult latLon(const Message& m, PendingHalf& pending, double& target, std::uint32_t field, double limit);

  IdentifierMap map_;
  CanAerospaceState state_;
  PendingHalf latPending_, lonPending_;
  std::array<std::uint64_t, kFeedStatusCount> counts_{};
};

}  // namespace skyig::protocol::canaerospace
