#ifndef SKYIG_NIGHT_UNITS_GLSL
#define SKYIG_NIGHT_UNITS_GLSL
// Surface brightness units of the night sky, in one place (docs/night-sky-diffuse.md, "Units").
//
// - mag/arcsec^2 (V) -> cd/m^2: L = 10.8e4 * 10^(-0.4 m). A V = 0 star gives 2.54e-6 lx
//   (Allen's Astrophysical Quantities, 4th ed.); spread over one square
//   arcsecond (2.3504e-11 sr) that is 1.081e5 cd/m^2 (Garstang 1986 and Cinzano et al. 2001
//   use the same 10.8e4 figure). So 22 mag/arcsec^2 = 1.71e-4 cd/m^2.
// - S10: the surface brightness of one V = 10 star per square degree (Leinert et al. 1998): 27.78 mag/arcsec^2, i.e. 10.8e4 * 1e-4 / 3600^2 = 8.333e-7 cd/m^2 per S10.
// - Leinert et al. 1998 table 17 gives the zodiacal light at 500 nm in
//   1e-8 W m^-2 sr^-1 um^-1; for the solar spectrum 1 S10 = 1.28e-8 W m^-2 sr^-1 um^-1
//   (Leinert et al. 1998: the ecliptic pole's 77 table units are the 60 S10 they quote for it).

const Float kMagArcsec2ZeroPointCdM2 = 10.8e4;
const Float kS10CdM2 = 10.8e4 * 1.0e-4 / (3600.0 * 3600.0);
const Float kLeinertUnitsPerS10 = 1.28;  // table 17 units (1e-8 W m^-2 sr^-1 um^-1) per S10

Float magArcsec2ToCdM2(Float mag) { return kMagArcsec2ZeroPointCdM2 * pow(10.0, -0.4 * mag); }

Float cdM2ToMagArcsec2(Float luminance) { return -2.5 * log(luminance / kMagArcsec2ZeroPointCdM2) / log(10.0); }

Float s10ToCdM2(Float s10) { return s10 * kS10CdM2; }

Float s10ToMagArcsec2(Float s10) { return cdM2ToMagArcsec2(s10ToCdM2(s10)); }

Float leinertToS10(Float tableValue) { return tableValue / kLeinertUnitsPerS10; }

#endif
