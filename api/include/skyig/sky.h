#pragma once
// skyig's public API: the sky and its light for another image generator (docs/library.md).
//
//   skyig::Sky sky;                                      // the configuration's sky, its tables loaded
//   sky.update(observer, hostSeconds);                   // once per host frame
//   const skyig::Light light = sky.light();              // the host's sun, moon and ambient
//   skyig::SkyDraw draw(getProcAddress);                 // with the host's GL context current
//   draw.draw(sky, view, projection, viewport);          // the sky behind the host's terrain
//
// Frames and units. Directions are unit vectors in the observer's local east-north-up frame
// (x east, y north, z up). Illuminance in lux, radiance in cd/m^2, colours linear Rec.709: a
// "colour" has Rec.709 luminance 0.2126729 R + 0.7151522 G + 0.0721750 B = 1; a "Rec.709"
// triple of lux or cd/m^2 has the photometric value as its luminance.
//
// Stability: these headers (skyig/sky.h, skyig/gl_sky.h) are the whole interface; every other
// type stays inside the library (pointer to implementation), so a new skyig with the same
// kApiVersion is a drop-in replacement. Errors are thrown as skyig::Error, whose message names
// the file, line and value at fault.
#include <array>
#include <memory>
#include <stdexcept>
#include <string>

#define SKYIG_API __attribute__((visibility("default")))

namespace skyig {

// Incremented by a change that would break a client built against an older header.
inline constexpr int kApiVersion = 1;

// The library's version, "major.minor.patch".
SKYIG_API const char* version();

class SKYIG_API Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Settings {
  // A skyig configuration file (TOML, as `skyig serve` reads: docs/configuration.md); empty:
  // the built-in defaults. Its [[channel]] and [host] sections are not used here.
  std::string configFile;
  // Overrides of the configuration's [sky] model ("physical", "preetham", "cie:<type>") and
  // table size ("small", "medium", "default"); empty: the configuration's.
  std::string model;
  std::string tables;
  // The visibility (km) the physical sky starts with; 0: the configuration's ([atmosphere]
  // visibility_km, else the clean medium's).
  double visibilityKm = 0.0;
  // false: the eye is adapted at once to every frame (stills); true: it adapts in time on the
  // host's clock (Sky::update's hostSeconds), as a pilot's does.
  bool temporalAdaptation = true;
};

// UTC as the host's sim clock gives it.
struct Utc {
  int year = 2026;
  int month = 6;
  int day = 21;
  double secondsOfDay = 12 * 3600.0;
};

// Where the eye is and when: WGS 84 geodetic position, height above the ellipsoid.
struct Observer {
  double latitudeDeg = 47.2603;
  double longitudeDeg = 11.3439;
  double heightM = 581.0;
  Utc utc;
  double pressureHpa = 1013.25;  // the air at the observer: refraction of sun, moon and stars
  double temperatureC = 15.0;
};

// The weather the physical sky is built for; a visibility of 0: the configuration's atmosphere.
struct Weather {
  double visibilityKm = 0.0;  // meteorological visibility (Koschmieder): 0, or 0.01 km (10 m) and more
  double humidityPct = 0.0;   // relative humidity: the aerosol's growth
};

using Vec3 = std::array<double, 3>;

// A direct light at the observer after extinction by the atmosphere.
struct DirectLight {
  Vec3 direction{0.0, 0.0, -1.0};  // towards the body
  double normalLux = 0.0;          // on a surface facing it
  double horizontalLux = 0.0;      // on a horizontal surface (0 below the horizon)
  Vec3 colour{1.0, 1.0, 1.0};      // luminance 1
};

struct Light {
  DirectLight sun;
  DirectLight moon;
  // The sky (without the discs, which are the lights above) on a horizontal surface.
  double ambientHorizontalLux = 0.0;
  Vec3 ambientHorizontalRec709{0.0, 0.0, 0.0};
  // The sky radiance's first nine real spherical-harmonic coefficients per Rec.709 channel
  // (cd/m^2), in Ramamoorthi & Hanrahan's (2001) order L00, L1-1, L10, L11, L2-2, L2-1, L20,
  // L21, L22 with x, y, z = east, north, up: irradianceFromSh turns them into the irradiance
  // on any normal (their eq. 13).
  std::array<Vec3, 9> skySh{};
  // The pilot's eye for this frame: the adaptation luminance (cd/m^2) skyig tone-maps with, and
  // the display gain of a not yet adapted eye, for a host that tone-maps itself.
  double adaptationLuminance = 1.0;
  double adaptationGain = 1.0;
};

// Irradiance (Rec.709 lux) on a surface of normal `normal` (normalised here; a zero or
// non-finite normal throws Error) from `light.skySh`.
SKYIG_API Vec3 irradianceFromSh(const Light& light, const Vec3& normal);

// Between the observer and a point: a surface of radiance L seen there is L * transmittance +
// inScattered (per Rec.709 channel).
struct AerialPerspective {
  Vec3 transmittance{1.0, 1.0, 1.0};
  Vec3 inScattered{0.0, 0.0, 0.0};  // cd/m^2
};

// One of the host's cloud layers (CIGI Weather Control layers 1-3; docs/clouds.md): its type
// ("altocumulus", "altostratus", "cirrocumulus", "cirrostratus", "cirrus", "cumulonimbus",
// "cumulus", "nimbostratus", "stratocumulus", "stratus"), base and thickness in metres above the
// ground, the share of the sky it covers, and the horizontal wind that moves it.
struct CloudLayer {
  bool enabled = false;
  std::string type = "stratus";
  double baseM = 0.0;
  double thicknessM = 0.0;
  double coveragePct = 100.0;
  double windSpeedMps = 0.0;
  double windFromDeg = 0.0;  // the direction it blows from, degrees from true north
  int severity = 2;          // CIGI's 0-5: the water content inside, 0.49-2.9 times the type's (2)
};

// One Sky per observer (eye point); use it from one thread at a time. Its tables load once and
// a background thread builds new ones when the weather asks for them.
class SKYIG_API Sky {
 public:
  // Loads the configuration, the star catalogue and (physical sky) the atmosphere's tables:
  // from skyig's cache, else precomputed once (seconds to minutes: in an OpenGL context of its
  // own when one can be made, which leaves the caller's current context as it was). Data files
  // are found beside the library (<libdir>/../share/skyig) unless SKYIG_DATA_DIR says otherwise.
  explicit Sky(const Settings& settings = {});
  ~Sky();
  Sky(Sky&&) noexcept;
  Sky& operator=(Sky&&) noexcept;
  Sky(const Sky&) = delete;
  Sky& operator=(const Sky&) = delete;

  // A frame of the host: the observer at `hostSeconds` of the host's own monotonic clock (the
  // eye adapts on it; a step back or a jump of more than ten minutes of sim time or 20 km
  // starts the eye adapted). A new weather requests new tables, blended from cached ones until
  // they are built. Throws Error for a value the sky cannot use (NaN, latitude beyond 90 deg,
  // ...), keeping the last good frame.
  void update(const Observer& observer, double hostSeconds, const Weather& weather = {});

  // The host's cloud layers from the next update() on; a layer not enabled keeps the
  // configuration's ([[weather.cloud]]). Throws Error naming the layer and the value it cannot
  // draw (an unknown type, a thickness not above 0, a coverage outside 0-100, NaN), keeping the
  // layers it had.
  void setClouds(const std::array<CloudLayer, 3>& layers);

  // The light of the last update (before any: the defaults' observer).
  Light light() const;
  // The sun's direct light through the cloud layers at a point `offsetEnuM` metres from the
  // observer (a terrain point: its cloud shadow), 0 to 1: 1 without clouds, the deck's
  // transmittance along the sun's ray under a cloud, 1 in a broken deck's gap, as skyig draws
  // them. Physical sky only: throws Error under an analytic one, and for a non-finite offset.
  double sunThroughClouds(const Vec3& offsetEnuM) const;
  // Aerial perspective to a point `offsetEnuM` metres from the observer. Physical sky only:
  // throws Error under an analytic one, and for a non-finite offset.
  AerialPerspective aerialPerspective(const Vec3& offsetEnuM) const;

  struct Impl;
  // Throws Error for a Sky that was moved from (as every member does).
  const Impl& impl() const;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace skyig
