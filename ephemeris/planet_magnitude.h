#pragma once
// Apparent visual magnitudes of the naked-eye planets: Mallama & Hilton (2018), "Computing
// apparent planetary magnitudes for The Astronomical Almanac", Astronomy and Computing 25, 10,
// eq. 2-8 (Saturn with its rings, eq. 10, valid for phase angles up to 6.5 degrees).

namespace skyig::ephemeris {

enum class Planet { Mercury, Venus, Mars, Jupiter, Saturn };

// V magnitude from heliocentric distance r and observer distance delta (au), phase angle in
// radians and, for Saturn, the ring tilt towards the observer (radians; ignored otherwise).
double planetMagnitude(Planet planet, double rAu, double deltaAu, double phaseAngleRad,
                       double saturnRingTiltRad = 0.0);

}  // namespace skyig::ephemeris
