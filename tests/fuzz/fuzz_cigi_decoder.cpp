// libFuzzer target: any bytes as one CIGI message. The decoder must not crash or read out
// of bounds (ASan/UBSan), and what it decodes must re-encode stably: encoding the decoded
// packets and decoding again gives the same bytes (NaN-safe, unlike comparing floats).
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "protocol/cigi/decoder.h"
#include "protocol/cigi/encoder.h"

using namespace skyig::protocol;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const cigi::DecodedMessage d = cigi::decodeMessage(std::span(data, size));
  if (d.error && d.error->offset > size) std::abort();
  if (d.packets.empty()) return 0;
  const cigi::PacketId first = cigi::packetId(d.packets.front());
  if (first != cigi::PacketId::igControl && first != cigi::PacketId::startOfFrame) return 0;
  // CIGI 3.3 and the CIGI 4.0 subset each re-encode in their own version.
  const auto encode = d.majorVersion == 4 ? cigi::encodeMessage4 : cigi::encodeMessage;
  std::vector<std::uint8_t> once, twice;
  if (!encode(d.packets, d.byteOrder, once).empty()) std::abort();  // decoded values always fit
  const cigi::DecodedMessage again = cigi::decodeMessage(once);
  if (!again.ok() || again.packets.size() != d.packets.size() || again.majorVersion != d.majorVersion) std::abort();
  if (!encode(again.packets, again.byteOrder, twice).empty() || once != twice) std::abort();
  return 0;
}
