#pragma once
// `skyig replay`: a recording drives the same decoders, host state, sky state and renderer as
// the live node, on the recording's clock. Frame k shows the host state at
// t_first_record + k / frame_rate; nothing depends on how fast the machine renders, so two
// replays of one file write byte-identical EXR files.
#include "node/config/node_config.h"
#include "node/transport/udp_socket.h"

#include <atomic>
#include <optional>
#include <string>

namespace skyig::services {

struct ReplayOptions {
  NodeConfig config;
  std::string recording;
  double frameRateHz = 30.0;
  bool realtime = false;            // pace frames (or --send) as recorded; else as fast as possible
  std::string outDir;               // images; empty: none
  int every = 1;                    // write every Nth frame
  bool writeExr = true;
  bool writePng = true;
  std::string channel;              // one channel by name; empty: the first, or all with allChannels
  bool allChannels = false;
  std::optional<std::string> from;  // a frame number, or a sim time (UTC, ISO 8601)
  std::optional<std::string> to;
  std::string dumpStatePath;
  std::optional<Endpoint> sendTo;   // re-transmit to a live IG instead of rendering
  bool skipBad = false;
  int port = 0;                     // only datagrams to this UDP port (0: all)
  // A pause between two records longer than this (a host paused, a corrupt timestamp) is
  // skipped: the next frame shows the next record, instead of 1/frame rate steps through it.
  double maxGapS = 60.0;
  bool progress = true;
  // Set (by a signal) to end the replay after the frame in hand: what was written stays, the
  // result says how far it got. Also ends a wait for tables.
  const std::atomic<bool>* stop = nullptr;
};

struct ReplayResult {
  std::uint64_t events = 0;
  std::uint64_t frames = 0;           // frames computed (the worker stepped to each)
  std::uint64_t framesDrawn = 0;      // frames drawn: those written (every Nth)
  std::uint64_t imagesWritten = 0;
  std::uint64_t skippedRecords = 0;   // bad records passed over (--skip-bad)
  std::uint64_t skippedGaps = 0;      // pauses longer than maxGapS not rendered
  double skippedGapSeconds = 0.0;
  double wallSeconds = 0.0;
  bool stopped = false;  // ended early by ReplayOptions::stop
};

// Throws RecordingError (a bad recording), ConfigError (bad options) or the render errors.
ReplayResult replay(const ReplayOptions& options);

}  // namespace skyig::services
