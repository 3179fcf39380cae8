#pragma once
// Who drives the node, and when a host's stream starts again (pure: no sockets are opened, no
// threads). A CIGI host is followed one session at a time: one sender address and port, whose
// frame numbers run on from one datagram to the next. A restarted host (a frame number that does
// not run on, a silence, or IG Control's Reset/Standby mode) starts a new session at once, so a
// restart is followed within one host frame; reordering is dropped only inside a session and a
// bounded window. Another source port on the followed address takes over only as a restarted
// process would: its frame numbers starting again while the followed stream is well under way,
// Reset/Standby, or the followed port gone silent for one and a half of its frame intervals;
// otherwise it is a second host beside the live one (an old process still sending, a test tool)
// and changes nothing. A sender outside `host.allowed`, or another address while the followed
// host is alive, changes nothing either.
#include "protocol/cigi/packets.h"
#include "node/host/host_state.h"
#include "node/host/sender.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace skyig::services {

// An IPv4 address or CIDR block ("10.1.2.3", "192.168.0.0/16").
struct AddressRange {
  std::uint32_t network = 0;  // host byte order, masked
  int prefixLength = 32;
  bool contains(std::uint32_t address) const;  // host byte order
  std::string toString() const;
};

// Parses "A.B.C.D" or "A.B.C.D/N" (N in 0..32; the host bits must be zero, as a typo such as
// "10.1.2.3/8" is more likely than a deliberate one); throws std::invalid_argument naming the
// text and what is wrong.
AddressRange parseAddressRange(const std::string& text);

// The default of host.allowed: loopback (127.0.0.0/8), the private networks of RFC 1918
// (10/8, 172.16/12, 192.168/16) and link-local 169.254/16, where a simulator LAN lives.
std::vector<AddressRange> privateNetworks();

struct HostSessionSettings {
  std::vector<AddressRange> allowed = privateNetworks();  // "0.0.0.0/0": any address
  // A host silent for longer than this (s) is gone: the next datagram starts a new session,
  // and another allowed address may take over.
  double sessionGapS = 1.0;
  // A frame number up to this many behind the last is stale (reordered) and dropped; further
  // behind, or more than this many ahead, is a restarted host.
  std::uint32_t staleFrames = 30;
};

// Why a session started. Stable values: they index counters.
enum class SessionReason : std::uint8_t {
  first = 0,   // the first host datagram
  newAddress,  // another allowed address, after the followed host fell silent
  newPort,     // the followed address from another source port (a restarted process)
  gap,         // the host was silent for longer than sessionGapS
  frameJump,   // a frame number far behind or far ahead of the last
  resetMode,   // IG Control entered Reset/Standby mode: the host is (re)starting
};
inline constexpr std::size_t kSessionReasonCount = 6;
const char* toString(SessionReason r);

enum class Admission : std::uint8_t {
  apply,       // the next frame of the current session
  newSession,  // apply, as the first frame of a new session
  stale,       // an older frame of the current session (reordered): drop
  notAllowed,  // the sender is outside host.allowed: drop
  otherHost,   // another address while the followed host is alive: drop
  otherPort,   // another port of the followed address, not a restart of it: drop
};

struct SessionDecision {
  Admission admission = Admission::apply;
  SessionReason reason = SessionReason::first;  // for newSession
};

class HostSessions {
 public:
  explicit HostSessions(HostSessionSettings settings = {});

  // Decides what a host message (its IG Control) from `from`, received at `arrival`, is,
  // and moves the session on accordingly.
  SessionDecision admit(const Sender& from, const protocol::cigi::IgControl& ig, Clock::time_point arrival);

  bool active() const { return active_; }
  const Sender& host() const { return host_; }          // the followed sender
  std::uint64_t sessions() const { return sessions_; }  // sessions started so far
  const HostSessionSettings& settings() const { return settings_; }

 private:
  bool allowed(std::uint32_t address) const;
  void start(const Sender& from, const protocol::cigi::IgControl& ig, Clock::time_point arrival);

  HostSessionSettings settings_;
  bool active_ = false;
  Sender host_{};
  std::uint64_t sessions_ = 0;
  std::uint32_t lastFrame_ = 0;    // newest frame applied in this session
  protocol::cigi::IgMode lastMode_ = protocol::cigi::IgMode::operate;
  Clock::time_point lastHeard_{};  // last datagram of the followed host, stale ones included
  double intervalS_ = 0.0;         // the followed host's datagram interval, smoothed (0: not yet known)
  // Whether a datagram from another port of the followed address starts a new session.
  bool otherPortTakesOver(const protocol::cigi::IgControl& ig, double silentS) const;
};

}  // namespace skyig::services
