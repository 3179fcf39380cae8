#pragma once
// Typed CIGI 3.3 packets (SISO-STD-013-2002 ICD, version 3.3). Field names, units and
// enumerations as the ICD defines them: angles in degrees, lengths in metres, latitude and
// longitude in degrees (WGS-84 unless the host redefines the earth model), temperatures in
// degrees Celsius, pressure in hPa (millibars), percentages 0..100. Layouts: protocol/cigi/layouts.h.
// Constant fields (packet id and size, version numbers, the byte-swap magic, reserved bytes)
// are not members: the encoder writes them and the decoder checks them.
#include <cstdint>
#include <optional>
#include <variant>

namespace skyig::protocol::cigi {

// Packet identifiers of the packets skyig understands (ICD table "CIGI packet identifiers").
enum class PacketId : std::uint8_t {
  igControl = 1,
  entityControl = 2,
  rateControl = 8,
  celestialSphereControl = 9,
  atmosphereControl = 10,
  environmentalRegionControl = 11,
  weatherControl = 12,
  viewControl = 16,
  sensorControl = 17,
  viewDefinition = 21,
  startOfFrame = 101,
};

inline constexpr std::uint8_t kMajorVersion = 3;
inline constexpr std::uint8_t kMinorVersion = 3;    // written by the encoder
inline constexpr std::uint16_t kByteSwapMagic = 0x8000;

// --- Host to IG ------------------------------------------------------------------------------

enum class IgMode : std::uint8_t { resetStandby = 0, operate = 1, debug = 2, offline = 3 };

// IG Control (id 1, 24 bytes in 3.2/3.3). First packet of every host-to-IG message.
struct IgControl {
  std::int8_t databaseNumber = 0;   // 0: no change; 1..127: load that database
  IgMode igMode = IgMode::operate;
  bool timestampValid = false;
  bool extrapolationEnable = false;  // global extrapolation/interpolation (smoothing) enable
  std::uint32_t hostFrameNumber = 0;
  std::uint32_t timestamp = 0;       // 10 us ticks since an arbitrary reference
  std::uint32_t lastIgFrameNumber = 0;
  bool operator==(const IgControl&) const = default;
};

enum class EntityState : std::uint8_t { inactiveStandby = 0, active = 1, destroyed = 2 };
enum class GroundClamp : std::uint8_t { none = 0, nonConformal = 1, conformal = 2 };
enum class AnimationState : std::uint8_t { stop = 0, pause = 1, play = 2, resume = 3 };

// Entity Control (id 2, 48 bytes). Entity 0 is the ownship by convention.
struct EntityControl {
  std::uint16_t entityId = 0;
  EntityState entityState = EntityState::active;
  bool attached = false;               // attach state: position is an offset from parentId
  bool collisionDetectionEnable = false;
  bool inheritAlpha = false;
  GroundClamp groundOceanClamp = GroundClamp::none;
  bool animationDirectionBackward = false;
  bool animationLoop = false;
  AnimationState animationState = AnimationState::stop;
  bool extrapolationEnable = false;
  std::uint8_t alpha = 255;
  std::uint16_t entityType = 0;
  std::uint16_t parentId = 0;
  float rollDeg = 0.0f;    // -180..180, right wing down positive
  float pitchDeg = 0.0f;   // -90..90, nose up positive
  float yawDeg = 0.0f;     // 0..360, true heading
  double latitudeDeg = 0.0;   // or X offset (m) when attached
  double longitudeDeg = 0.0;  // or Y offset (m) when attached
  double altitudeM = 0.0;     // or Z offset (m) when attached
  bool operator==(const EntityControl&) const = default;
};

// Rate Control (id 8, 32 bytes in 3.2/3.3): rates for IG-side extrapolation.
struct RateControl {
  std::uint16_t entityId = 0;
  std::uint8_t articulatedPartId = 0;
  bool applyToArticulatedPart = false;
  bool localCoordinates = false;  // coordinate system: false = world/parent, true = local (body)
  float xRateMps = 0.0f;
  float yRateMps = 0.0f;
  float zRateMps = 0.0f;
  float rollRateDegps = 0.0f;
  float pitchRateDegps = 0.0f;
  float yawRateDegps = 0.0f;
  bool operator==(const RateControl&) const = default;
};

// Celestial Sphere Control (id 9, 16 bytes). Hour and minute only: 3.3 carries no seconds.
struct CelestialSphereControl {
  std::uint8_t hour = 12;    // 0..23 UTC
  std::uint8_t minute = 0;   // 0..59
  bool ephemerisModelEnable = true;
  bool sunEnable = true;
  bool moonEnable = true;
  bool starFieldEnable = true;
  bool dateTimeValid = true;
  std::uint32_t date = 1012000;  // MMDDYYYY as a decimal number (see cigi/date.h)
  float starFieldIntensityPct = 100.0f;
  // CIGI 4.0 only (0 <= seconds < 60): 3.3 carries no seconds, so a 3.3 message decodes
  // with 0 here and the 3.3 encoder does not send it.
  float seconds = 0.0f;
  bool operator==(const CelestialSphereControl&) const = default;
};

// Atmosphere Control (id 10, 32 bytes): global atmospheric properties.
struct AtmosphereControl {
  bool atmosphericModelEnable = false;
  std::uint8_t globalHumidityPct = 0;
  float airTemperatureC = 15.0f;
  float visibilityRangeM = 50000.0f;
  float horizontalWindSpeedMps = 0.0f;
  float verticalWindSpeedMps = 0.0f;
  float windDirectionDeg = 0.0f;
  float barometricPressureHpa = 1013.25f;
  bool operator==(const AtmosphereControl&) const = default;
};

enum class RegionState : std::uint8_t { inactive = 0, active = 1, destroyed = 2 };

// Environmental Region Control (id 11, 48 bytes): a rounded rectangle of weather.
struct EnvironmentalRegionControl {
  std::uint16_t regionId = 0;
  RegionState regionState = RegionState::active;
  bool mergeWeather = false;
  bool mergeAerosol = false;
  bool mergeMaritime = false;
  bool mergeTerrestrial = false;
  double latitudeDeg = 0.0;
  double longitudeDeg = 0.0;
  float sizeXM = 0.0f;
  float sizeYM = 0.0f;
  float cornerRadiusM = 0.0f;
  float rotationDeg = 0.0f;
  float transitionPerimeterM = 0.0f;
  bool operator==(const EnvironmentalRegionControl&) const = default;
};

enum class WeatherScope : std::uint8_t { global = 0, regional = 1, entity = 2 };

// Weather Control (id 12, 56 bytes; CIGI 4.0: 0x0B, 72 bytes): one weather layer, globally, in a
// region or on an entity. The top scud and top transition band are CIGI 4.0's alone.
struct WeatherControl {
  std::uint16_t entityRegionId = 0;
  std::uint8_t layerId = 0;        // 0 ground fog, 1-3 cloud layers, 4 rain, 5 snow, ...
  std::uint8_t humidityPct = 0;
  bool weatherEnable = false;
  bool scudEnable = false;
  bool randomWindsEnable = false;
  bool randomLightningEnable = false;
  std::uint8_t cloudType = 0;      // 0 none .. 10 stratus, 11-15 other (4 bits)
  WeatherScope scope = WeatherScope::global;
  std::uint8_t severity = 0;       // 0..5 (3 bits)
  float airTemperatureC = 0.0f;
  float visibilityRangeM = 0.0f;
  float scudFrequencyPct = 0.0f;
  float coveragePct = 0.0f;
  float baseElevationM = 0.0f;
  float thicknessM = 0.0f;
  float transitionBandM = 0.0f;
  float horizontalWindSpeedMps = 0.0f;
  float verticalWindSpeedMps = 0.0f;
  float windDirectionDeg = 0.0f;
  float barometricPressureHpa = 0.0f;
  float aerosolConcentrationGpm3 = 0.0f;
  bool topScudEnable = false;        // 4.0
  float topScudFrequencyPct = 0.0f;  // 4.0
  float topTransitionBandM = 0.0f;   // 4.0
  bool operator==(const WeatherControl&) const = default;
};

// View Control (id 16, 32 bytes): eyepoint of a view (channel) relative to an entity.
struct ViewControl {
  std::uint16_t viewId = 0;
  std::uint8_t groupId = 0;
  bool xOffsetEnable = false;
  bool yOffsetEnable = false;
  bool zOffsetEnable = false;
  bool rollEnable = false;
  bool pitchEnable = false;
  bool yawEnable = false;
  std::uint16_t entityId = 0;
  float xOffsetM = 0.0f;   // body axes: x forward, y right, z down
  float yOffsetM = 0.0f;
  float zOffsetM = 0.0f;
  float rollDeg = 0.0f;
  float pitchDeg = 0.0f;
  float yawDeg = 0.0f;
  bool operator==(const ViewControl&) const = default;
};

enum class MirrorMode : std::uint8_t { none = 0, horizontal = 1, vertical = 2, both = 3 };

// View Definition (id 21, 32 bytes): the frustum of a view as four signed half-angles.
struct ViewDefinition {
  std::uint16_t viewId = 0;
  std::uint8_t groupId = 0;
  bool nearEnable = false;
  bool farEnable = false;
  bool leftEnable = false;
  bool rightEnable = false;
  bool topEnable = false;
  bool bottomEnable = false;
  MirrorMode mirrorMode = MirrorMode::none;
  std::uint8_t pixelReplicationMode = 0;  // 3 bits
  bool orthographic = false;              // projection type: false = perspective
  bool reorder = false;
  std::uint8_t viewType = 0;              // 3 bits, IG-defined
  float nearM = 0.0f;
  float farM = 0.0f;
  float leftDeg = 0.0f;
  float rightDeg = 0.0f;
  float topDeg = 0.0f;
  float bottomDeg = 0.0f;
  bool operator==(const ViewDefinition&) const = default;
};

enum class SensorPolarity : std::uint8_t { whiteHot = 0, blackHot = 1 };

// Sensor Control (id 17, 24 bytes): a sensor (in skyig the night-vision goggle) of a view.
// Gain, level, AC coupling and noise are fractions, 0..1. skyig has one sensor per view, the
// goggle: it accepts any Sensor ID and uses Sensor On/Off, Automatic Gain and Gain
// (node/host/cigi_state.cpp); the other fields are decoded and encoded but not used.
struct SensorControl {
  std::uint16_t viewId = 0;
  std::uint8_t sensorId = 0;
  bool sensorOn = false;
  SensorPolarity polarity = SensorPolarity::whiteHot;
  bool lineDropoutEnable = false;
  bool automaticGain = false;
  bool trackBlack = false;           // track white/black: false = white
  std::uint8_t trackMode = 0;        // 3 bits: 0 off, 1 force correlate, 2 scene, 3 target, 4 ship, 5-7 IG-defined
  bool gateAndTargetResponse = false;  // response type: false = gate position only
  float gain = 0.0f;
  float level = 0.0f;
  float acCoupling = 0.0f;
  float noise = 0.0f;
  bool operator==(const SensorControl&) const = default;
};

// --- IG to host ------------------------------------------------------------------------------

// Start of Frame (id 101, 24 bytes in 3.2/3.3). First packet of every IG-to-host message.
struct StartOfFrame {
  std::int8_t databaseNumber = 0;
  std::uint8_t igStatus = 0;  // 0 = normal, IG-defined otherwise
  IgMode igMode = IgMode::operate;
  bool timestampValid = false;
  bool hostDefinedEarthModel = false;  // earth reference model: false = WGS-84
  std::uint32_t igFrameNumber = 0;
  std::uint32_t timestamp = 0;  // 10 us ticks
  std::uint32_t lastHostFrameNumber = 0;
  bool operator==(const StartOfFrame&) const = default;
};

using Packet = std::variant<IgControl, EntityControl, RateControl, CelestialSphereControl,
                            AtmosphereControl, EnvironmentalRegionControl, WeatherControl,
                            ViewControl, ViewDefinition, SensorControl, StartOfFrame>;

// Number of alternatives of Packet, for per-type counters indexed by Packet::index().
inline constexpr std::size_t kPacketTypeCount = std::variant_size_v<Packet>;

// Packet id and size of each type, and a name for logs and statistics.
PacketId packetId(const Packet& p);
std::uint8_t packetSize(PacketId id);  // 0 when the id is not one skyig decodes
const char* packetName(PacketId id);
const char* packetName(std::size_t variantIndex);

// CIGI 4.0 (subset, see protocol/cigi/layouts4.h): 16-bit packet ids and sizes. The
// host-to-IG pose travels in Entity Position Control, decoded into EntityControl.
inline constexpr std::uint16_t kCigi4IgControl = 0x0000;
inline constexpr std::uint16_t kCigi4EntityPositionControl = 0x0001;
inline constexpr std::uint16_t kCigi4CelestialSphereControl = 0x0008;
inline constexpr std::uint16_t kCigi4AtmosphereControl = 0x0009;
inline constexpr std::uint16_t kCigi4WeatherControl = 0x000B;
inline constexpr std::uint16_t kCigi4ViewControl = 0x000F;
inline constexpr std::uint16_t kCigi4ViewDefinition = 0x0014;
inline constexpr std::uint16_t kCigi4SensorControl = 0x0010;
inline constexpr std::uint16_t kCigi4StartOfFrame = 0xFFFF;
// The CIGI 4 id and size of a packet type (size 0: no CIGI 4 mapping in skyig), and the
// variant index a CIGI 4 id decodes to (kPacketTypeCount: none).
std::uint16_t packetId4(std::size_t variantIndex);
std::uint16_t packetSize4(std::size_t variantIndex);
std::size_t variantIndexOf4(std::uint16_t id4);
const char* packetName4(std::uint16_t id4);

}  // namespace skyig::protocol::cigi
