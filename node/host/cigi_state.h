#pragma once
// Applies decoded CIGI host messages to the HostState (pure: no sockets, no threads).
#include "protocol/cigi/decoder.h"
#include "node/host/host_state.h"
#include "node/host/sim_clock.h"
#include "sky/camera.h"

#include <algorithm>
#include <optional>
#include <vector>

namespace skyig::services {

// The host's clock as the receiver last knew it: the minutes the host stated (SimClock) and the
// map from a local instant to the host's continuous time (its IG Control timestamps, or the
// arrival times when it sends none). A small value, so every snapshot carries its own copy and
// the worker and render threads evaluate the host's time at any instant without the tracker.
struct HostClock {
  SimClock clock;
  bool haveTimestamp = false;
  double timestampBaseS = 0.0;              // unwrapped timestamp seconds at timestampArrival
  Clock::time_point timestampArrival{};

  // The host's continuous time at a local instant, seconds.
  double continuousAt(Clock::time_point t) const;
  // UTC at a local instant, refined below the minute; nullopt before the host gave a time.
  std::optional<ephemeris::UtcTime> utcAt(Clock::time_point t) const { return clock.at(continuousAt(t)); }
};

// A timestamp step is bounded: further back than this (s) or further ahead than that is not
// the next tick of the same clock (a host whose clock was re-based), and the clock goes on from
// where it stands. Ahead allows a time-lapse host stamping its sim clock (the emulator's
// --speed 1e5 at 30 Hz steps 3333 s); back allows jitter (a reordered frame never gets here).
inline constexpr double kMaxTimestampBackS = 1.0;
inline constexpr double kMaxTimestampStepS = 3600.0;

class CigiStateTracker {
 public:
  // Applies every well-formed packet of a message received at `arrival`. A message is one host
  // frame: one with an invalid value (NaN, an out-of-range angle, an impossible date) is
  // refused whole, its frame number, timestamp and every other packet with it, and the state
  // and clock stay as they were; a goggle's bad gain alone is dropped while its switch applies
  // (CIGI's Sensor Control carries both). Returns the number of rejected values. Which messages are applied, in
  // which order, is the receiver's call (node/host/host_session.h): the tracker takes each
  // IG Control timestamp as the next step of the current session's clock.
  int apply(const protocol::cigi::DecodedMessage& message, Clock::time_point arrival);
  // The next message starts a new host session: its timestamp does not continue the last
  // one's, so the host's clock is re-anchored where it stands (it never jumps).
  void startSession() { sessionHasTimestamp_ = false; }
  // The host's time of the last message applied (s, on the continuous clock) and how fast the
  // host's clock runs (host seconds per local second, measured over a second or more: 1 for a
  // host that stamps real time, 90 for a 90x time-lapse that stamps its sim clock), when its IG
  // Control carried a timestamp that continued the clock and the rate is known.
  std::optional<HostTime> messageHostTime() const { return messageHostTime_; }
  // Timestamps that did not continue the host's clock (more than kMaxTimestampBackS back or
  // kMaxTimestampStepS ahead): the clock went on from where it stood.
  std::uint64_t timestampJumps() const { return timestampJumps_; }
  // View Control, View Definition and Sensor Control packets for a view id at or above the maximum
  // (host.max_views, at most kViewTableCapacity): counted and dropped.
  void setMaxViews(std::size_t n) { maxViews_ = std::min(n, kViewTableCapacity); }
  std::uint64_t droppedViews() const { return droppedViews_; }
  // The configured frusta of the node's channels (view n is channel n): a View Definition that
  // edits one edge of a pair is checked against the frustum it would produce with the other
  // edge as it stands (the host's last, else the channel's), so one edge moved past the other
  // is refused like a pair that crosses. Views without a channel are checked on the edges known.
  void setChannelFrusta(std::vector<sky::Frustum> frusta) { channelFrusta_ = std::move(frusta); }

  const HostState& state() const { return state_; }
  const HostClock& clock() const { return clock_; }

  // One packet's effect: whether it changed the state, and how many of its values were refused.
  // A packet can do both: a bad gain is refused while the goggle's switch still applies.
  struct Applied {
    bool changed = false;
    int rejected = 0;
    bool refusesFrame = true;  // a rejected value refuses the whole message
  };

 private:
  HostState state_;
  HostClock clock_;
  void anchorTimestamp(std::uint32_t timestamp, Clock::time_point arrival);
  void followTimestamp(std::uint32_t timestamp, Clock::time_point arrival);
  // The view a View Control, View Definition or Sensor Control names, or null (counted) beyond
  // host.max_views.
  ViewOverride* view(std::uint16_t viewId);
  // One packet applied to the state, one overload a packet type skyig reads.
  using Message = protocol::cigi::DecodedMessage;
  Applied on(const protocol::cigi::IgControl& p, const Message& m, Clock::time_point arrival);
  Applied on(const protocol::cigi::EntityControl& p, const Message& m, Clock::time_point arrival);
  Applied on(const protocol::cigi::RateControl& p, const Message& m, Clock::time_point arrival);
  Applied on(const protocol::cigi::CelestialSphereControl& p, const Message& m, Clock::time_point arrival);
  Applied on(const protocol::cigi::AtmosphereControl& p, const Message& m, Clock::time_point arrival);
  Applied on(const protocol::cigi::WeatherControl& p, const Message& m, Clock::time_point arrival);
  Applied on(const protocol::cigi::ViewControl& p, const Message& m, Clock::time_point arrival);
  Applied on(const protocol::cigi::ViewDefinition& p, const Message& m, Clock::time_point arrival);
  Applied on(const protocol::cigi::SensorControl& p, const Message& m, Clock::time_point arrival);
  // Every other packet (Environmental Region Control, an IG's Start of Frame): nothing for skyig.
  template <class Other>
  Applied on(const Other&, const Message&, Clock::time_point) {
    return {};
  }

  bool sessionHasTimestamp_ = false;  // lastTimestamp_ belongs to the current session
  std::size_t maxViews_ = kDefaultMaxViews;
  std::vector<sky::Frustum> channelFrusta_;
  std::uint64_t droppedViews_ = 0;
  std::uint32_t lastTimestamp_ = 0;   // IG Control timestamp, 10 us ticks
  // The continuous time as the anchor's time plus whole ticks since it (not a running sum of
  // steps): two nodes fed one stream from its start compute the same bits for every message,
  // so what they derive from it (the sun, the eye's adaptation) is identical, not merely close.
  double anchorBaseS_ = 0.0;
  std::int64_t ticksSinceAnchor_ = 0;
  std::optional<HostTime> messageHostTime_;
  std::uint64_t timestampJumps_ = 0;
  // The host clock's rate, from the continuous time at an anchor a second or more back.
  double rateAnchorS_ = 0.0;
  Clock::time_point rateAnchorArrival_{};
  std::optional<double> rate_;
};

}  // namespace skyig::services
