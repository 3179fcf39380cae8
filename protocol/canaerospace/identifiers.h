#pragma once
// Which CANaerospace identifier carries which host-state parameter. Defaults: the standard
// identifier distribution (CANaerospace V1.7 section 5, "Normal Operation Data"; the same
// numbers as libcanaerospace param_id/nod_default.h). A plain struct so the config layer can
// override any entry for a host that uses another distribution.
#include <cstdint>

namespace skyig::protocol::canaerospace {

struct IdentifierMap {
  std::uint32_t bodyPitch = 311;  // $137 body pitch angle, deg, nose up +   (FLOAT)
  std::uint32_t bodyRoll = 312;   // $138 body roll angle, deg, right wing down + (FLOAT)
  std::uint32_t heading = 321;    // $141 heading angle, deg, +-180           (FLOAT)
  std::uint32_t latitude = 1036;  // $40C GPS aircraft latitude, deg  (FLOAT or DOUBLEH+DOUBLEL)
  std::uint32_t longitude = 1037; // $40D GPS aircraft longitude, deg (FLOAT or DOUBLEH+DOUBLEL)
  // $40E GPS height above ellipsoid, m (FLOAT). skyig's altitude is height above the WGS-84
  // ellipsoid; a host sending true altitude (332) or baro-corrected altitude (320) sets it here.
  std::uint32_t altitude = 1038;
  std::uint32_t utc = 1200;       // $4B0 UTC, CHAR4 hh mm ss 00
  std::uint32_t date = 1206;      // $4B6 date, CHAR4 dd mm cc yy
  // Some devices send latitude/longitude as LONG in units of 1e-7 deg (e.g. XCSoar's driver);
  // accepted only when enabled.
  bool acceptLongLatLon1e7 = false;
  // Accept messages from this transmitting node only (0..255), e.g. when a redundant host
  // sends the same identifiers; -1 accepts every node.
  int nodeId = -1;
};

}  // namespace skyig::protocol::canaerospace
