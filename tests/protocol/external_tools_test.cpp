// Files skyig writes, read by the tools people will use on them: Wireshark's CIGI dissector
// (tshark) must decode the pcap with the values written, tcpdump must read the pcap, and
// can-utils' log2long must read the candump log. Each test skips, saying so, when the tool
// is not installed (Debian packages tshark, tcpdump, can-utils; deploy/setup.sh installs them).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>

#include "protocol/canaerospace/state_encoder.h"
#include "protocol/candump/candump.h"
#include "protocol/cigi/encoder.h"
#include "protocol/io/byte_sink.h"
#include "protocol/pcap/pcap_writer.h"
#include "tests/protocol/cigi_samples.h"
#include "tests/protocol/temp_path.h"

namespace skyig::protocol {
namespace {

bool haveTool(const char* name) {
  const std::string cmd = std::string("command -v ") + name + " >/dev/null 2>&1";
  return std::system(cmd.c_str()) == 0;
}

std::string run(const std::string& cmd) {
  std::string out;
  FILE* p = popen((cmd + " 2>&1").c_str(), "r");
  if (p == nullptr) return out;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  pclose(p);
  return out;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, sep)) parts.push_back(cur);
  if (!s.empty() && s.back() == sep) parts.emplace_back();
  return parts;
}

// Runs tshark on `file` and returns, for each record, field name -> value text.
std::vector<std::map<std::string, std::string>> tsharkFields(const std::string& file,
                                                             const std::vector<std::string>& fields) {
  std::string cmd = "tshark -r " + file + " -d udp.port==8004,cigi -d udp.port==8005,cigi -T fields -E separator=';'";
  for (const auto& f : fields) cmd += " -e " + f;
  std::vector<std::map<std::string, std::string>> rows;
  for (const std::string& line : split(run(cmd), '\n')) {
    if (line.empty() || line.find(';') == std::string::npos) continue;
    const auto values = split(line, ';');
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < fields.size() && i < values.size(); ++i) row[fields[i]] = values[i];
    rows.push_back(row);
  }
  return rows;
}

double num(const std::map<std::string, std::string>& row, const std::string& field) {
  const auto it = row.find(field);
  if (it == row.end() || it->second.empty()) {
    ADD_FAILURE() << "tshark gave no value for " << field;
    return std::numeric_limits<double>::quiet_NaN();
  }
  return std::stod(it->second);
}

std::string writeCigiPcap(ByteOrder order) {
  const std::string path = test::tempPath(std::string("cigi_") + toString(order)[0] + ".pcap");
  io::FileSink sink;
  EXPECT_TRUE(sink.open(path)) << sink.error();
  pcap::Writer w(sink);
  EXPECT_TRUE(w.open()) << w.error();
  std::vector<cigi::Packet> host = cigi::test::everyPacketType();
  const cigi::Packet sof = host.back();
  host.pop_back();
  std::vector<std::uint8_t> bytes;
  EXPECT_EQ(cigi::encodeMessage(host, order, bytes), "");
  const pcap::Endpoint hostEp{{10, 0, 0, 1}, 8005}, igEp{{10, 0, 0, 2}, 8004};
  EXPECT_TRUE(w.writeUdp(1782073800000000000, hostEp, igEp, bytes)) << w.error();
  const std::vector<cigi::Packet> igMessage{sof};
  EXPECT_EQ(cigi::encodeMessage(igMessage, order, bytes), "");
  EXPECT_TRUE(w.writeUdp(1782073800016666000, igEp, hostEp, bytes)) << w.error();
  return path;
}

TEST(ExternalTools, TsharkDecodesSkyigCigiPcapWithTheValuesWritten) {
  if (!haveTool("tshark")) GTEST_SKIP() << "tshark not installed (apt-get install tshark): Wireshark check skipped";
  const std::vector<cigi::Packet> sample = cigi::test::everyPacketType();
  const auto& ig = std::get<cigi::IgControl>(sample[0]);
  const auto& e = std::get<cigi::EntityControl>(sample[1]);
  const auto& r = std::get<cigi::RateControl>(sample[2]);
  const auto& c = std::get<cigi::CelestialSphereControl>(sample[3]);
  const auto& a = std::get<cigi::AtmosphereControl>(sample[4]);
  const auto& er = std::get<cigi::EnvironmentalRegionControl>(sample[5]);
  const auto& wc = std::get<cigi::WeatherControl>(sample[6]);
  const auto& vc = std::get<cigi::ViewControl>(sample[7]);
  const auto& vd = std::get<cigi::ViewDefinition>(sample[8]);
  const auto& sc = std::get<cigi::SensorControl>(sample[9]);
  const auto& sof = std::get<cigi::StartOfFrame>(sample[10]);
  const std::vector<std::string> fields{
      "cigi.byte_swap", "cigi.ig_control.db_number", "cigi.ig_control.host_frame_number",
      "cigi.ig_control.timestamp", "cigi.ig_control.last_ig_frame_number", "cigi.ig_control.minor_version",
      "cigi.entity_control.entity_id", "cigi.entity_control.roll", "cigi.entity_control.pitch",
      "cigi.entity_control.yaw", "cigi.entity_control.lat_xoff", "cigi.entity_control.lon_yoff",
      "cigi.entity_control.alt_zoff", "cigi.rate_control.x_rate", "cigi.rate_control.yaw_rate",
      "cigi.rate_control.coordinate_system", "cigi.celestial_sphere_control.hour",
      "cigi.celestial_sphere_control.minute", "cigi.celestial_sphere_control.date",
      "cigi.celestial_sphere_control.star_intensity", "cigi.celestial_sphere_control.moon_enable",
      "cigi.celestial_sphere_control.sun_enable", "cigi.atmosphere_control.humidity",
      "cigi.atmosphere_control.visibility_range", "cigi.atmosphere_control.air_temp",
      "cigi.atmosphere_control.barometric_pressure", "cigi.env_region_control.region_id",
      "cigi.env_region_control.lat", "cigi.env_region_control.lon", "cigi.env_region_control.size_x",
      "cigi.env_region_control.merge_terrestrial", "cigi.weather_control.humidity",
      "cigi.weather_control.visibility_range", "cigi.weather_control.cloud_type", "cigi.weather_control.severity",
      "cigi.weather_control.scope", "cigi.weather_control.layer_id", "cigi.weather_control.scud_enable",
      "cigi.weather_control.scud_frequency", "cigi.weather_control.coverage", "cigi.weather_control.base_elevation",
      "cigi.weather_control.thickness", "cigi.weather_control.transition_band", "cigi.weather_control.horiz_wind",
      "cigi.weather_control.wind_direction", "cigi.view_control.view_id", "cigi.view_control.group_id",
      "cigi.view_control.yaw", "cigi.view_control.zoff", "cigi.view_def.view_id", "cigi.view_def.left",
      "cigi.view_def.right", "cigi.view_def.top", "cigi.view_def.bottom", "cigi.view_def.far",
      "cigi.view_def.mirror_mode", "cigi.view_def.projection_type", "cigi.sensor_control.view_id",
      "cigi.sensor_control.sensor_id", "cigi.sensor_control.sensor_on_off", "cigi.sensor_control.auto_gain",
      "cigi.sensor_control.track_mode", "cigi.sensor_control.gain", "cigi.sensor_control.noise", "cigi.sof.ig_frame_number",
      "cigi.sof.last_host_frame_number", "cigi.sof.ig_mode", "cigi.sof.earth_reference_model",
      "cigi.sof.minor_version"};
  for (ByteOrder order : {ByteOrder::big, ByteOrder::little}) {
    SCOPED_TRACE(toString(order));
    const std::string path = writeCigiPcap(order);
    const auto rows = tsharkFields(path, fields);
    ASSERT_EQ(rows.size(), 2u) << run("tshark -r " + path + " -d udp.port==8004,cigi -V");
    const auto& h = rows[0];
    EXPECT_EQ(h.at("cigi.byte_swap"), order == ByteOrder::big ? "0x8000" : "0x0080");
    EXPECT_EQ(num(h, "cigi.ig_control.db_number"), ig.databaseNumber);
    EXPECT_EQ(num(h, "cigi.ig_control.host_frame_number"), ig.hostFrameNumber);
    EXPECT_EQ(num(h, "cigi.ig_control.timestamp"), ig.timestamp);
    EXPECT_EQ(num(h, "cigi.ig_control.last_ig_frame_number"), ig.lastIgFrameNumber);
    EXPECT_EQ(num(h, "cigi.ig_control.minor_version"), 3);
    EXPECT_EQ(num(h, "cigi.entity_control.entity_id"), e.entityId);
    EXPECT_NEAR(num(h, "cigi.entity_control.roll"), e.rollDeg, 1e-4);
    EXPECT_NEAR(num(h, "cigi.entity_control.pitch"), e.pitchDeg, 1e-4);
    EXPECT_NEAR(num(h, "cigi.entity_control.yaw"), e.yawDeg, 1e-4);
    EXPECT_NEAR(num(h, "cigi.entity_control.lat_xoff"), e.latitudeDeg, 1e-12);
    EXPECT_NEAR(num(h, "cigi.entity_control.lon_yoff"), e.longitudeDeg, 1e-12);
    EXPECT_NEAR(num(h, "cigi.entity_control.alt_zoff"), e.altitudeM, 1e-9);
    EXPECT_NEAR(num(h, "cigi.rate_control.x_rate"), r.xRateMps, 1e-4);
    EXPECT_NEAR(num(h, "cigi.rate_control.yaw_rate"), r.yawRateDegps, 1e-4);
    EXPECT_EQ(num(h, "cigi.rate_control.coordinate_system"), 1);
    EXPECT_EQ(num(h, "cigi.celestial_sphere_control.hour"), c.hour);
    EXPECT_EQ(num(h, "cigi.celestial_sphere_control.minute"), c.minute);
    EXPECT_EQ(num(h, "cigi.celestial_sphere_control.date"), c.date);
    EXPECT_NEAR(num(h, "cigi.celestial_sphere_control.star_intensity"), c.starFieldIntensityPct, 1e-4);
    EXPECT_EQ(num(h, "cigi.celestial_sphere_control.moon_enable"), 0);
    EXPECT_EQ(num(h, "cigi.celestial_sphere_control.sun_enable"), 1);
    EXPECT_EQ(num(h, "cigi.atmosphere_control.humidity"), a.globalHumidityPct);
    EXPECT_NEAR(num(h, "cigi.atmosphere_control.visibility_range"), a.visibilityRangeM, 1e-2);
    EXPECT_NEAR(num(h, "cigi.atmosphere_control.air_temp"), a.airTemperatureC, 1e-4);
    EXPECT_NEAR(num(h, "cigi.atmosphere_control.barometric_pressure"), a.barometricPressureHpa, 1e-3);
    EXPECT_EQ(num(h, "cigi.env_region_control.region_id"), er.regionId);
    EXPECT_NEAR(num(h, "cigi.env_region_control.lat"), er.latitudeDeg, 1e-12);
    EXPECT_NEAR(num(h, "cigi.env_region_control.lon"), er.longitudeDeg, 1e-12);
    EXPECT_NEAR(num(h, "cigi.env_region_control.size_x"), er.sizeXM, 1e-2);
    EXPECT_EQ(num(h, "cigi.env_region_control.merge_terrestrial"), 1);
    EXPECT_EQ(num(h, "cigi.weather_control.humidity"), wc.humidityPct);
    EXPECT_NEAR(num(h, "cigi.weather_control.visibility_range"), wc.visibilityRangeM, 1e-3);
    EXPECT_EQ(num(h, "cigi.weather_control.cloud_type"), wc.cloudType);
    EXPECT_EQ(num(h, "cigi.weather_control.severity"), wc.severity);
    EXPECT_EQ(num(h, "cigi.weather_control.scope"), static_cast<int>(wc.scope));
    // A cloud layer's own fields, as the node reads them (node/host/cigi_state.cpp).
    EXPECT_EQ(num(h, "cigi.weather_control.layer_id"), wc.layerId);
    EXPECT_EQ(num(h, "cigi.weather_control.scud_enable"), 1);
    EXPECT_NEAR(num(h, "cigi.weather_control.scud_frequency"), wc.scudFrequencyPct, 1e-4);
    EXPECT_NEAR(num(h, "cigi.weather_control.coverage"), wc.coveragePct, 1e-4);
    EXPECT_NEAR(num(h, "cigi.weather_control.base_elevation"), wc.baseElevationM, 1e-3);
    EXPECT_NEAR(num(h, "cigi.weather_control.thickness"), wc.thicknessM, 1e-3);
    EXPECT_NEAR(num(h, "cigi.weather_control.transition_band"), wc.transitionBandM, 1e-3);
    EXPECT_NEAR(num(h, "cigi.weather_control.horiz_wind"), wc.horizontalWindSpeedMps, 1e-4);
    EXPECT_NEAR(num(h, "cigi.weather_control.wind_direction"), wc.windDirectionDeg, 1e-3);
    EXPECT_EQ(num(h, "cigi.view_control.view_id"), vc.viewId);
    EXPECT_EQ(num(h, "cigi.view_control.group_id"), vc.groupId);
    EXPECT_NEAR(num(h, "cigi.view_control.yaw"), vc.yawDeg, 1e-4);
    EXPECT_NEAR(num(h, "cigi.view_control.zoff"), vc.zOffsetM, 1e-5);
    EXPECT_EQ(num(h, "cigi.view_def.view_id"), vd.viewId);
    EXPECT_NEAR(num(h, "cigi.view_def.left"), vd.leftDeg, 1e-4);
    EXPECT_NEAR(num(h, "cigi.view_def.right"), vd.rightDeg, 1e-4);
    EXPECT_NEAR(num(h, "cigi.view_def.top"), vd.topDeg, 1e-4);
    EXPECT_NEAR(num(h, "cigi.view_def.bottom"), vd.bottomDeg, 1e-4);
    EXPECT_NEAR(num(h, "cigi.view_def.far"), vd.farM, 1.0);
    EXPECT_EQ(num(h, "cigi.view_def.mirror_mode"), static_cast<int>(vd.mirrorMode));
    EXPECT_EQ(num(h, "cigi.view_def.projection_type"), 1);
    EXPECT_EQ(num(h, "cigi.sensor_control.view_id"), sc.viewId);
    EXPECT_EQ(num(h, "cigi.sensor_control.sensor_id"), sc.sensorId);
    EXPECT_EQ(num(h, "cigi.sensor_control.sensor_on_off"), 1);
    EXPECT_EQ(num(h, "cigi.sensor_control.auto_gain"), 0);
    EXPECT_EQ(num(h, "cigi.sensor_control.track_mode"), sc.trackMode);
    EXPECT_NEAR(num(h, "cigi.sensor_control.gain"), sc.gain, 1e-6);
    EXPECT_NEAR(num(h, "cigi.sensor_control.noise"), sc.noise, 1e-6);
    const auto& s = rows[1];
    EXPECT_EQ(num(s, "cigi.sof.ig_frame_number"), sof.igFrameNumber);
    EXPECT_EQ(num(s, "cigi.sof.last_host_frame_number"), sof.lastHostFrameNumber);
    EXPECT_EQ(num(s, "cigi.sof.ig_mode"), static_cast<int>(sof.igMode));
    EXPECT_EQ(num(s, "cigi.sof.earth_reference_model"), 1);
    EXPECT_EQ(num(s, "cigi.sof.minor_version"), 3);
    // No expert info (malformed packets, bad checksums) anywhere.
    const std::string expert = run("tshark -r " + path + " -d udp.port==8004,cigi -d udp.port==8005,cigi -o udp.check_checksum:TRUE -o ip.check_checksum:TRUE -z expert,warn -q");
    EXPECT_EQ(expert.find("Malformed"), std::string::npos) << expert;
    EXPECT_EQ(expert.find("Bad checksum"), std::string::npos) << expert;
    EXPECT_EQ(expert.find("incorrect"), std::string::npos) << expert;
    std::filesystem::remove(path);
  }
}

TEST(ExternalTools, TcpdumpReadsSkyigPcap) {
  if (!haveTool("tcpdump")) GTEST_SKIP() << "tcpdump not installed (apt-get install tcpdump): check skipped";
  const std::string path = writeCigiPcap(ByteOrder::little);
  const std::string out = run("tcpdump -n -r " + path);
  EXPECT_NE(out.find("10.0.0.1.8005 > 10.0.0.2.8004: UDP, length 344"), std::string::npos) << out;
  EXPECT_NE(out.find("10.0.0.2.8004 > 10.0.0.1.8005: UDP, length 24"), std::string::npos) << out;
  // tcpdump -vv verifies the UDP checksums it can.
  const std::string verbose = run("tcpdump -vv -n -r " + path);
  EXPECT_EQ(verbose.find("bad udp cksum"), std::string::npos) << verbose;
  EXPECT_EQ(verbose.find("bad cksum"), std::string::npos) << verbose;
  std::filesystem::remove(path);
}

TEST(ExternalTools, CanUtilsReadsSkyigCandumpLog) {
  if (!haveTool("log2long")) GTEST_SKIP() << "can-utils not installed (apt-get install can-utils): check skipped";
  const std::string path = test::tempPath("candump_test.log");
  {
    io::FileSink sink;
    ASSERT_TRUE(sink.open(path)) << sink.error();
    candump::Writer w(sink);
    canaerospace::CanFrame f = canaerospace::toFrame(canaerospace::makeFloat(311, 10, 4.0f, 0));
    ASSERT_TRUE(w.write(1782073800000000, "can0", f));
    f.canId = 0x1ABCDEF0 | canaerospace::kCanEffFlag;
    f.len = 3;
    ASSERT_TRUE(w.write(1782073800000123, "can0", f));
  }
  const std::string out = run("log2long < " + path);
  EXPECT_NE(out.find("(1782073800.000000)  can0       137   [8]  0A 02 00 00 40 80 00 00"), std::string::npos) << out;
  EXPECT_NE(out.find("(1782073800.000123)  can0  1ABCDEF0   [3]  0A 02 00"), std::string::npos) << out;
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace skyig::protocol
