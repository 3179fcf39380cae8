#include "node/transport/cigi_receiver.h"

#include <spdlog/spdlog.h>

#include <array>

namespace skyig::services {

CigiReceiver::CigiReceiver(NodeStats& stats, Latest<HostSnapshot>& out, HostSessionSettings sessions)
    : stats_(stats), out_(out), sessions_(std::move(sessions)) {}

// How many warnings of one kind were held back since the last one logged, as a suffix.
static std::string heldBackSuffix(std::uint64_t heldBack) {
  return heldBack ? fmt::format(" ({} more since the last warning)", heldBack) : "";
}

void CigiReceiver::run(UdpSocket& socket, const std::atomic<bool>& stop) {
  std::array<std::uint8_t, 65536> buffer{};
  sockaddr_in kernelFrom{};
  while (!stop.load(std::memory_order_relaxed)) {
    const std::size_t n = socket.receive(buffer, kernelFrom, std::chrono::milliseconds(50));
    if (n == 0) continue;
    const Sender from = toSender(kernelFrom);
    const auto arrival = Clock::now();
    if (recorder_) {
      const auto unixNs = std::chrono::duration_cast<std::chrono::nanoseconds>(
                              std::chrono::system_clock::now().time_since_epoch()).count();
      if (!recorder_->record(std::span(buffer.data(), n), from, unixNs)) {
        // A full disk stops the recording, never the node.
        spdlog::error("recording stopped: {}", recorder_->error());
        stats_.recordErrors.fetch_add(1, std::memory_order_relaxed);
        recorder_ = nullptr;
      } else {
        stats_.recorded.fetch_add(1, std::memory_order_relaxed);
      }
    }
    handle(std::span(buffer.data(), n), from, arrival);
  }
}

void CigiReceiver::handle(std::span<const std::uint8_t> datagram, const Sender& from, Clock::time_point arrival) {
  stats_.datagrams.fetch_add(1, std::memory_order_relaxed);
  stats_.bytes.fetch_add(datagram.size(), std::memory_order_relaxed);
  protocol::cigi::decodeMessage(datagram, decoded_);
  for (const auto& p : decoded_.packets) stats_.packets[p.index()].fetch_add(1, std::memory_order_relaxed);
  stats_.skippedPackets.fetch_add(decoded_.skippedPackets, std::memory_order_relaxed);
  if (decoded_.error) {
    // Rejected whole: a CIGI message is one host frame, and the packets before the fault (its
    // IG Control's frame number and timestamp among them) are no more trustworthy than the
    // rest; half a frame would show a state the host never had. The next frame follows.
    stats_.malformedDatagrams.fetch_add(1, std::memory_order_relaxed);
    stats_.errors[static_cast<std::size_t>(decoded_.error->kind)].fetch_add(1, std::memory_order_relaxed);
    if (std::uint64_t heldBack = 0; malformedWarnings_.allow(arrival, &heldBack))
      spdlog::warn("malformed CIGI datagram from {}: {}{}", from.toString(), decoded_.error->describe(),
                   heldBackSuffix(heldBack));
    return;
  }
  const auto* ig =
      decoded_.packets.empty() ? nullptr : std::get_if<protocol::cigi::IgControl>(&decoded_.packets.front());
  if (!ig) {  // an IG's Start of Frame: not a host message
    stats_.notHostMessages.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  const SessionDecision d = sessions_.admit(from, *ig, arrival);
  switch (d.admission) {
    case Admission::stale:
      stats_.staleMessages.fetch_add(1, std::memory_order_relaxed);
      return;  // nothing newer to publish
    case Admission::notAllowed:
    case Admission::otherHost:
    case Admission::otherPort: {
      const bool outside = d.admission == Admission::notAllowed;
      (outside ? stats_.notAllowedDatagrams : stats_.otherHostDatagrams).fetch_add(1, std::memory_order_relaxed);
      const std::string why =
          outside ? std::string("not in host.allowed")
          : d.admission == Admission::otherHost
              ? "following the host at " + sessions_.host().toString()
              : "a second sender on the followed host's address, which is sending from " + sessions_.host().toString() +
                    " (a restarted host would count its frames again or enter Reset/Standby)";
      if (std::uint64_t heldBack = 0; foreignWarnings_.allow(arrival, &heldBack))
        spdlog::warn("ignoring CIGI from {}: {}{}", from.toString(), why, heldBackSuffix(heldBack));
      return;
    }
    case Admission::newSession:
      stats_.sessions[static_cast<std::size_t>(d.reason)].fetch_add(1, std::memory_order_relaxed);
      // Who drives the node is worth a line whenever it changes; a restart of the same host
      // is routine.
      if (from.address != lastHostAddress_ || d.reason == SessionReason::first)
        spdlog::warn("following the CIGI host at {} (session {}: {})", from.toString(),
                     sessions_.sessions(), toString(d.reason));
      else
        spdlog::info("new session {} of the CIGI host at {}: {}", sessions_.sessions(), from.toString(),
                     toString(d.reason));
      lastHostAddress_ = from.address;
      tracker_.startSession();
      predictor_ = OwnshipPredictor{};  // no velocity across a restart: the host may have moved anywhere
      break;
    case Admission::apply: break;
  }
  const std::uint64_t jumpsBefore = tracker_.timestampJumps();
  const std::uint64_t droppedViewsBefore = tracker_.droppedViews();
  const int rejected = tracker_.apply(decoded_, arrival);
  stats_.timestampJumps.fetch_add(tracker_.timestampJumps() - jumpsBefore, std::memory_order_relaxed);
  stats_.rejectedValues.fetch_add(static_cast<std::uint64_t>(rejected), std::memory_order_relaxed);
  stats_.droppedViews.fetch_add(tracker_.droppedViews() - droppedViewsBefore, std::memory_order_relaxed);
  const HostState& s = tracker_.state();
  if (s.ownshipValid && s.ownshipTime == arrival)
    predictor_.addSample(s.ownship, arrival, s.rates, tracker_.messageHostTime());
  else if (s.ownshipValid && !predictor_.valid())  // a new session that has not moved it yet: held
    predictor_.addSample(s.ownship, s.ownshipTime, {});
  // The session's host travels with the state, so a frame answers the host whose state it shows.
  out_.publish(HostSnapshot{s, predictor_, tracker_.clock(), sessions_.host(), Clock::now(), {}});
  stats_.arrivalToVisible.add(std::chrono::duration<double, std::micro>(Clock::now() - arrival).count());
}

}  // namespace skyig::services
