#pragma once
// Turns a host state into the CANaerospace frames a host would send, one message per
// parameter, with a message code per identifier that increments each message (spec V1.7
// section 3: "incremented by 1 for every message of that ID"). For tests and the emulator.
#include <map>
#include <vector>

#include "protocol/canaerospace/identifiers.h"
#include "protocol/canaerospace/state_decoder.h"

namespace skyig::protocol::canaerospace {

enum class LatLonEncoding : std::uint8_t { floatSingle, doublePair, long1e7 };

class StateEncoder {
 public:
  explicit StateEncoder(IdentifierMap map = {}, std::uint8_t nodeId = 1,
                        LatLonEncoding latLon = LatLonEncoding::doublePair)
      : map_(map), nodeId_(nodeId), latLon_(latLon) {}

  // Frames for the fields of `s` named by `fields` (Field bits). Heading goes out in +-180.
  std::vector<CanFrame> encode(const CanAerospaceState& s, std::uint32_t fields = 0xFF);

 private:
  std::uint8_t nextCode(std::uint32_t id, std::uint8_t step = 1);

  IdentifierMap map_;
  std::uint8_t nodeId_;
  LatLonEncoding latLon_;
  std::map<std::uint32_t, std::uint8_t> codes_;
};

}  // namespace skyig::protocol::canaerospace
