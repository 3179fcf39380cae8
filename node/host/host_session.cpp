#include "node/host/host_session.h"

#include <algorithm>
#include <stdexcept>

namespace skyig::services {

namespace cigi = protocol::cigi;

bool AddressRange::contains(std::uint32_t address) const {
  const std::uint32_t mask = prefixLength == 0 ? 0u : ~0u << (32 - prefixLength);
  return (address & mask) == network;
}

std::string AddressRange::toString() const { return ipv4ToString(network) + "/" + std::to_string(prefixLength); }

AddressRange parseAddressRange(const std::string& text) {
  const std::size_t slash = text.find('/');
  const std::string address = text.substr(0, slash);
  const std::optional<std::uint32_t> a = parseIpv4(address);
  if (!a)
    throw std::invalid_argument("\"" + text + "\" is not an IPv4 address or CIDR block (A.B.C.D or A.B.C.D/N)");
  AddressRange r;
  if (slash != std::string::npos) {
    const std::string bits = text.substr(slash + 1);
    char* end = nullptr;
    const long n = std::strtol(bits.c_str(), &end, 10);
    if (bits.empty() || *end != '\0' || n < 0 || n > 32)
      throw std::invalid_argument("\"" + text + "\": the prefix length after '/' must be 0..32");
    r.prefixLength = static_cast<int>(n);
  }
  const std::uint32_t mask = r.prefixLength == 0 ? 0u : ~0u << (32 - r.prefixLength);
  if ((*a & ~mask) != 0)
    throw std::invalid_argument("\"" + text + "\": address bits set beyond the /" + std::to_string(r.prefixLength) +
                                " prefix (did you mean " +
                                AddressRange{*a & mask, r.prefixLength}.toString() + "?)");
  r.network = *a;
  return r;
}

std::vector<AddressRange> privateNetworks() {
  return {parseAddressRange("127.0.0.0/8"), parseAddressRange("10.0.0.0/8"), parseAddressRange("172.16.0.0/12"),
          parseAddressRange("192.168.0.0/16"), parseAddressRange("169.254.0.0/16")};
}

const char* toString(SessionReason r) {
  switch (r) {
    case SessionReason::first: return "first";
    case SessionReason::newAddress: return "new_address";
    case SessionReason::newPort: return "new_port";
    case SessionReason::gap: return "gap";
    case SessionReason::frameJump: return "frame_jump";
    case SessionReason::resetMode: return "reset_mode";
  }
  return "?";
}

HostSessions::HostSessions(HostSessionSettings settings) : settings_(std::move(settings)) {}

bool HostSessions::allowed(std::uint32_t address) const {
  for (const AddressRange& r : settings_.allowed)
    if (r.contains(address)) return true;
  return false;
}

void HostSessions::start(const Sender& from, const cigi::IgControl& ig, Clock::time_point arrival) {
  active_ = true;
  host_ = from;
  ++sessions_;
  lastFrame_ = ig.hostFrameNumber;
  lastHeard_ = arrival;
  lastMode_ = ig.igMode;
  intervalS_ = 0.0;
}

// A restarted process counts its frames from about 0 while the old stream is far on, or enters
// Reset/Standby; or the followed port has fallen silent for 1.5 of its intervals (one missed
// frame and a half: the next datagram of the other port after the followed host stopped).
bool HostSessions::otherPortTakesOver(const cigi::IgControl& ig, double silentS) const {
  if (silentS > settings_.sessionGapS) return true;
  if (intervalS_ > 0.0 && silentS > std::max(1.5 * intervalS_, 0.02)) return true;
  if (ig.igMode == cigi::IgMode::resetStandby) return true;
  return ig.hostFrameNumber <= settings_.staleFrames && lastFrame_ > 2 * settings_.staleFrames;
}

SessionDecision HostSessions::admit(const Sender& from, const cigi::IgControl& ig, Clock::time_point arrival) {
  if (!allowed(from.address)) return {Admission::notAllowed};
  const double silentS = std::chrono::duration<double>(arrival - lastHeard_).count();
  const bool sameAddress = active_ && from.address == host_.address;
  // Another address never interrupts a live host: a stray or spoofed datagram changes nothing.
  if (active_ && !sameAddress && silentS <= settings_.sessionGapS) return {Admission::otherHost};

  auto restart = [&](SessionReason why) {
    start(from, ig, arrival);
    return SessionDecision{Admission::newSession, why};
  };
  if (!active_) return restart(SessionReason::first);
  if (!sameAddress) return restart(SessionReason::newAddress);
  if (from.port != host_.port) {
    if (!otherPortTakesOver(ig, silentS)) return {Admission::otherPort};
    return restart(SessionReason::newPort);
  }
  // Entering Reset/Standby (a host held in it keeps one session: no session per datagram).
  const bool entersReset = ig.igMode == cigi::IgMode::resetStandby && lastMode_ != cigi::IgMode::resetStandby;
  lastMode_ = ig.igMode;
  if (entersReset) return restart(SessionReason::resetMode);
  if (silentS > settings_.sessionGapS) return restart(SessionReason::gap);
  // Frame numbers in serial-number order (they wrap at 2^32), within a bounded window.
  const std::int64_t step = static_cast<std::int32_t>(ig.hostFrameNumber - lastFrame_);
  const auto window = static_cast<std::int64_t>(settings_.staleFrames);
  if (step < -window || step > window) return restart(SessionReason::frameJump);
  // The interval between the followed host's datagrams, smoothed over about ten of them.
  intervalS_ = intervalS_ > 0.0 ? 0.9 * intervalS_ + 0.1 * silentS : silentS;
  lastHeard_ = arrival;
  if (step < 0) return {Admission::stale};
  lastFrame_ = ig.hostFrameNumber;
  return {Admission::apply};
}

}  // namespace skyig::services
