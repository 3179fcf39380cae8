#include "protocol/canaerospace/state_encoder.h"

#include <cmath>

namespace skyig::protocol::canaerospace {

std::uint8_t StateEncoder::nextCode(std::uint32_t id, std::uint8_t step) {
  std::uint8_t& c = codes_[id];
  const std::uint8_t now = c;
  c = static_cast<std::uint8_t>(c + step);
  return now;
}

std::vector<CanFrame> StateEncoder::encode(const CanAerospaceState& s, std::uint32_t fields) {
  std::vector<CanFrame> out;
  auto latLon = [&](std::uint32_t id, double v) {
    switch (latLon_) {
      case LatLonEncoding::floatSingle:
        out.push_back(toFrame(makeFloat(id, nodeId_, static_cast<float>(v), nextCode(id))));
        break;
      case LatLonEncoding::doublePair:
        for (const Message& m : makeDoublePair(id, nodeId_, v, nextCode(id, 2))) out.push_back(toFrame(m));
        break;
      case LatLonEncoding::long1e7:
        out.push_back(toFrame(makeLong(id, nodeId_, static_cast<std::int32_t>(std::lround(v * 1e7)), nextCode(id))));
        break;
    }
  };
  auto single = [&](std::uint32_t id, double v) {
    out.push_back(toFrame(makeFloat(id, nodeId_, static_cast<float>(v), nextCode(id))));
  };
  if ((fields & kLatitude) != 0) latLon(map_.latitude, s.latitudeDeg);
  if ((fields & kLongitude) != 0) latLon(map_.longitude, s.longitudeDeg);
  if ((fields & kAltitude) != 0) single(map_.altitude, s.altitudeM);
  if ((fields & kHeading) != 0) single(map_.heading, s.headingDeg > 180.0 ? s.headingDeg - 360.0 : s.headingDeg);
  if ((fields & kPitch) != 0) single(map_.bodyPitch, s.pitchDeg);
  if ((fields & kRoll) != 0) single(map_.bodyRoll, s.rollDeg);
  if ((fields & kUtcTime) != 0)
    out.push_back(toFrame(makeChar4(map_.utc, nodeId_,
                                    {static_cast<std::uint8_t>(s.hour), static_cast<std::uint8_t>(s.minute),
                                     static_cast<std::uint8_t>(s.second), 0},
                                    nextCode(map_.utc))));
  if ((fields & kDate) != 0)
    out.push_back(toFrame(makeChar4(map_.date, nodeId_,
                                    {static_cast<std::uint8_t>(s.day), static_cast<std::uint8_t>(s.month),
                                     static_cast<std::uint8_t>(s.year / 100), static_cast<std::uint8_t>(s.year % 100)},
                                    nextCode(map_.date))));
  return out;
}

}  // namespace skyig::protocol::canaerospace
