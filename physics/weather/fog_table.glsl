#ifndef SKYIG_WEATHER_FOG_TABLE_GLSL
#define SKYIG_WEATHER_FOG_TABLE_GLSL
// The weather's layers along every view of one eye, as a table by the view's cosine mu
// (physics/weather/fog_table.h): the layers are spheres about the planet's centre and the eye is
// on the vertical, so what they do to a view (dim what lies behind by a transmittance, add their
// own light) depends on mu alone. The sky pass reads one texel pair per pixel instead of solving
// each layer's chords. u = (1 + sign(mu) sqrt(|mu|)) / 2: fine steps at the horizon, where a
// layer's top seen from above and the ground's edge are.
Float fogTableU(Float mu) { return 0.5 * (1.0 + sign(mu) * sqrt(abs(mu))); }
Float fogTableMu(Float u) {
  Float s = 2.0 * u - 1.0;
  return sign(s) * s * s;
}

#endif
