#ifndef SKYIG_WEATHER_FOG_LAYER_PARAMETERS_GLSL
#define SKYIG_WEATHER_FOG_LAYER_PARAMETERS_GLSL
// The parameters of a fog layer (physics/weather/fog_layer.glsl), a struct of its own so that the
// C++ side can pass it between translation units (physics/weather/weather_physics.h).
// One layer; extinction 0: no fog. Heights in metres above the ground (a sphere of
// planet_radius): kept apart from the radius so that single precision holds them to the
// millimetre (a radius near 6.4e6 m holds half metres).
struct FogLayer {
  Float planet_radius;
  Float bottom_height;
  Float top_height;
  Float extinction;      // per metre, at every wavelength (Koschmieder: 3.912 / visibility)
  Float asymmetry;       // g of the particles' phase function
  Float ground_albedo;   // the ground under the layer
  vec3 top_irradiance;   // linear Rec.709 lux on a horizontal surface at the top, from above
  vec3 albedo;           // the particles' single-scattering albedo per Rec.709 channel (1: water)
  Float band_height;     // the transition band above the top, metres (0: a hard edge)
  Float bottom_band_height;  // below a raised bottom (a fog's: band_height; a deck's base its own), metres
  // A cloud deck's (physics/weather/cloud_deck.h; 0 for fog): the expected share of the sky it
  // leaves clear (1 - coverage; the sky pass draws where, from the deck's field), and the b of the
  // law (1 + b mu) its base and top shine by.
  Float gap;
  Float limb_darkening;
};

// A layer's own radiance at one eye's depth in it (fogEye), linear Rec.709 cd/m^2: looking straight
// up (the downward flux over pi) and straight down (the upward one). The same for every view of a
// frame, so the sky pass gets it from the CPU instead of solving the slab per pixel.
struct FogEye {
  vec3 looking_up;
  vec3 looking_down;
  Float inside;          // 0 at the layer's boundary (or outside it), towards 1 deep in it
  Float limb_darkening;  // the layer's
};

#endif
