#ifndef SKYIG_COMMON_CONSTANTS_GLSL
#define SKYIG_COMMON_CONSTANTS_GLSL
// Numbers shared by every model. Physics files use Float (float on the GPU, double in C++).

const Float PI = 3.14159265358979323846;
const Float DEG = PI / 180.0;
const Float LOG10_E = 0.43429448190325182765;  // 1 / ln(10): GLSL has no log10

Float logTen(Float x) { return log(x) * LOG10_E; }

// The sun seen from the earth at 1 AU: mean angular radius (Bruneton 2017 uses 0.2678 deg;
// the IAU nominal solar radius gives 0.2666 deg) and the extraterrestrial illuminance on a
// surface normal to it, 128 klx (CIE 110-1994; Darula, Kittler & Gueymard 2005 give 128 klx).
const Float SUN_ANGULAR_RADIUS = 0.2666 * DEG;
const Float SOLAR_ILLUMINANCE_LX = 128000.0;

#endif
