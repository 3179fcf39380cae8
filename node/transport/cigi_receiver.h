#pragma once
// The receiver thread of a CIGI node: datagrams in, decoded, admitted by the host session
// (node/host/host_session.h: who may drive, restarts, reordering), applied to the host state and
// published whole (latest wins). A malformed datagram is rejected whole, counted and logged at
// a limited rate; the last good state is kept.
#include "node/host/host_session.h"
#include "node/host/host_snapshot.h"
#include "node/common/latest.h"
#include "node/host/node_stats.h"
#include "node/transport/udp_socket.h"
#include "node/common/warning_throttle.h"
#include "sky/channel.h"

#include <atomic>
#include <mutex>
#include <optional>
#include <vector>

namespace skyig::services {

// Something that keeps every datagram as it arrived (serve --record); record() returns false
// once it can no longer write, and is not called again.
class DatagramRecorder {
 public:
  virtual ~DatagramRecorder() = default;
  virtual bool record(std::span<const std::uint8_t> datagram, const Sender& from, std::int64_t unixTimeNs) = 0;
  virtual std::string error() const = 0;
};

class CigiReceiver {
 public:
  CigiReceiver(NodeStats& stats, Latest<HostSnapshot>& out, HostSessionSettings sessions = {});
  // Receives from `socket` until stop is set (checks it at least every 50 ms).
  void run(UdpSocket& socket, const std::atomic<bool>& stop);
  // Handles one datagram: the loop's body, and what replay feeds with recorded datagrams
  // and recorded arrival times.
  void handle(std::span<const std::uint8_t> datagram, const Sender& from, Clock::time_point arrival);
  void setRecorder(DatagramRecorder* recorder) { recorder_ = recorder; }
  // host.max_views (View Controls for higher ids are counted: NodeStats::droppedViews) and the
  // node's channels, view n the n-th (a View Definition is checked against the frustum it makes).
  void setViews(std::size_t maxViews, const std::vector<sky::ChannelConfig>& channels) {
    tracker_.setMaxViews(maxViews);
    std::vector<sky::Frustum> frusta;
    for (const sky::ChannelConfig& c : channels) frusta.push_back(c.frustum);
    tracker_.setChannelFrusta(std::move(frusta));
  }

 private:
  DatagramRecorder* recorder_ = nullptr;
  NodeStats& stats_;
  HostPublisher out_;
  HostSessions sessions_;
  CigiStateTracker tracker_;
  OwnshipPredictor predictor_;
  protocol::cigi::DecodedMessage decoded_;
  // At most one warning a second per kind, saying how many were held back: a flood of bad or
  // foreign datagrams must not flood the log.
  WarningThrottle malformedWarnings_{std::chrono::seconds(1)}, foreignWarnings_{std::chrono::seconds(1)};
  std::uint32_t lastHostAddress_ = 0;  // the address of the last session's host (host order)
};

}  // namespace skyig::services
