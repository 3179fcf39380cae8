#include "services/cigi_receiver.h"

#include <spdlog/spdlog.h>

#include <array>

namespace skyig::services {

CigiReceiver::CigiReceiver(NodeStats& stats, Latest<HostSnapshot>& out) : stats_(stats), out_(out) {}

void CigiReceiver::run(UdpSocket& socket, const std::atomic<bool>& stop) {
  std::array<std::uint8_t, 65536> buffer{};
  sockaddr_in from{};
  while (!stop.load(std::memory_order_relaxed)) {
    const std::size_t n = socket.receive(buffer, from, std::chrono::milliseconds(50));
    if (n == 0) continue;
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

void CigiReceiver::handle(std::span<const std::uint8_t> datagram, const sockaddr_in& from, Clock::time_point arrival) {
  stats_.datagrams.fetch_add(1, std::memory_order_relaxed);
  stats_.bytes.fetch_add(datagram.size(), std::memory_order_relaxed);
  protocol::cigi::decodeMessage(datagram, decoded_);
  for (const auto& p : decoded_.packets) stats_.packets[p.index()].fetch_add(1, std::memory_order_relaxed);
  stats_.skippedPackets.fetch_add(decoded_.skippedPackets, std::memory_order_relaxed);
  if (decoded_.error) {
    stats_.malformedDatagrams.fetch_add(1, std::memory_order_relaxed);
    stats_.errors[static_cast<std::size_t>(decoded_.error->kind)].fetch_add(1, std::memory_order_relaxed);
    // At most one warning a second, saying how many were held back.
    if (arrival - lastWarning_ > std::chrono::seconds(1)) {
      spdlog::warn("malformed CIGI datagram from {}: {}{}", fromSockaddr(from).toString(), decoded_.error->describe(),
                   suppressedWarnings_ ? fmt::format(" ({} more since the last warning)", suppressedWarnings_) : "");
      lastWarning_ = arrival;
      suppressedWarnings_ = 0;
    } else {
      ++suppressedWarnings_;
    }
  }
  if (decoded_.packets.empty()) return;
  const std::uint64_t staleBefore = tracker_.staleMessages();
  const std::uint64_t droppedViewsBefore = tracker_.droppedViews();
  const int rejected = tracker_.apply(decoded_, arrival);
  stats_.rejectedValues.fetch_add(static_cast<std::uint64_t>(rejected), std::memory_order_relaxed);
  stats_.droppedViews.fetch_add(tracker_.droppedViews() - droppedViewsBefore, std::memory_order_relaxed);
  if (tracker_.staleMessages() != staleBefore) {
    stats_.staleMessages.fetch_add(1, std::memory_order_relaxed);
    return;  // nothing newer to publish
  }
  const HostState& s = tracker_.state();
  if (s.ownshipValid && s.ownshipTime == arrival) predictor_.addSample(s.ownship, arrival, s.rates);
  // The sender travels with the state, so a frame answers the host whose state it shows.
  out_.emplace(s, predictor_, tracker_.clock(), from, Clock::now());
  stats_.arrivalToVisible.add(std::chrono::duration<double, std::micro>(Clock::now() - arrival).count());
}

}  // namespace skyig::services
