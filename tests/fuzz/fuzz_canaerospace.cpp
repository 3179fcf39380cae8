// libFuzzer target: bytes as a sequence of CAN frames (4 id bytes, 1 length, 8 data) fed to
// the CANaerospace state decoder; a frame that parses must survive toFrame/parseFrame.
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "protocol/canaerospace/state_decoder.h"

using namespace skyig::protocol::canaerospace;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  StateDecoder decoder;
  constexpr std::size_t kRecord = 13;
  for (std::size_t off = 0; off + kRecord <= size; off += kRecord) {
    CanFrame f;
    std::memcpy(&f.canId, data + off, 4);
    f.len = data[off + 4];
    std::memcpy(f.data.data(), data + off + 5, 8);
    decoder.feed(f);
    Message m, back;
    if (parseFrame(f, m) == FrameError::none) {
      if (parseFrame(toFrame(m), back) != FrameError::none || !(back == m)) std::abort();
    }
  }
  const CanAerospaceState& s = decoder.state();
  if (s.has(kLatitude) && !(s.latitudeDeg >= -90.0 && s.latitudeDeg <= 90.0)) std::abort();
  if (s.has(kHeading) && !(s.headingDeg >= 0.0 && s.headingDeg <= 360.0)) std::abort();
  return 0;
}
