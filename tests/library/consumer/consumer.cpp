// A host's first use of skyig: the sun, the sky's ambient light and the haze to a point 20 km
// away, at the default place on midsummer's afternoon. Prints them as key=value lines.
#include <skyig/sky.h>

#include <cstdio>
#include <exception>

int main() {
  try {
    skyig::Settings settings;
    settings.tables = "small";
    settings.temporalAdaptation = false;
    skyig::Sky sky(settings);
    skyig::Observer observer;  // Innsbruck
    observer.utc = {2026, 6, 21, 11 * 3600.0};
    sky.update(observer, 0.0);
    const skyig::Light light = sky.light();
    const skyig::AerialPerspective haze = sky.aerialPerspective({0.0, 20000.0, 0.0});
    std::printf("version=%s\napi=%d\nsun_up=%.6f\nsun_horizontal_lux=%.6g\nambient_lux=%.6g\n"
                "transmittance_20km_green=%.6f\n",
                skyig::version(), skyig::kApiVersion, light.sun.direction[2], light.sun.horizontalLux,
                light.ambientHorizontalLux, haze.transmittance[1]);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
}
