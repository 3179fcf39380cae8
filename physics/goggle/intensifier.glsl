#ifndef SKYIG_GOGGLE_INTENSIFIER_GLSL
#define SKYIG_GOGGLE_INTENSIFIER_GLSL
// The image intensifier of a night-vision goggle: how the NVIS radiance of the scene becomes
// photoelectrons on the photocathode, light on the phosphor screen, and the noise and halo of
// both; written once for the goggle pass (render/passes/goggle/goggle*.frag) and, through physics/
// goggle_physics.h, for the CPU and the tests (docs/nvis.md gives every figure's source).
//
// The numbers are a third-generation (GaAs photocathode, filmed microchannel plate) ANVIS-class
// goggle's. The tube's figures are the US Army's Omnibus ("Omni") procurement minimums for
// MX-10160 tubes as compiled by the night-vision community's public wiki (nv-intl, "Tubes"):
// Omni IV-V (1996-1999) 64 lp/mm, S/N 21, 1800 uA/lm at 2856 K, gain 40000-70000 fL/fc, MTF
// 0.92/0.80/0.61/0.38 at 2.5/7.5/15/25 lp/mm, halo 1.25 mm, P43; Omni VII (2006) S/N 28,
// 2200 uA/lm, halo 0.70 mm. Where a figure is an estimate it says so: the goggle makers' data
// sheets were not at hand for this work.
#include "physics/common/constants.glsl"

// The objective (ANVIS class): 27 mm focal length at f/1.23, the 40 deg field on an 18 mm
// photocathode (2 f tan 20 deg = 19.7 mm, the tube's useful diameter). Transmittance: an
// estimate for a coated multi-element lens.
const Float kObjectiveFocalLengthM = 0.027;
const Float kObjectiveFNumber = 1.23;
const Float kObjectiveTransmittance = 0.85;

// Photocathode luminous sensitivity to a 2856 K (CIE illuminant A) source, A/lm: Omni IV-V's
// 1800 uA/lm.
const Float kCathodeSensitivityAPerLm = 1.8e-3;
// The microchannel plate's excess noise factor F = 1 + var(g) / mean(g)^2 of its gain g per
// photoelectron: 1.7 to 2.5 for filmed plates. skyig takes the gain's distribution to be
// exponential, the pulse-height distribution of a plate far from saturation, for which F is 2
// exactly; the model's signal-to-noise ratio at the standard's 108 microlux
// (goggleSignalToNoise) is then 30.9, a tenth above Omni VII's 28 and within the Gen III tubes'
// 21-28 and better. render/passes/goggle/goggle.frag draws the gain of k electrons as a sum of k exponentials.
const Float kExcessNoiseFactor = 2.0;
// The luminance gain at full voltage, (cd/m^2 on the screen) per (lux on the photocathode):
// 50000 fL/fc, within Omni IV-V's 40000-70000 fL/fc; 1 fL = 3.4263 cd/m^2, 1 fc = 10.7639 lux.
const Float kFootLambertCdM2 = 3.4262591;
const Float kFootCandleLux = 10.7639104;
const Float kMaxLuminanceGain = 50000.0 * kFootLambertCdM2 / kFootCandleLux;
// The automatic brightness control holds the screen's mean at the tube's maximum output
// brightness, about 2.5 fL (an estimate within the 2-3 fL quoted for Gen III tubes), by
// lowering the gain; below that the gain is at its maximum and the screen dims with the scene.
const Float kAbcScreenCdM2 = 2.5 * kFootLambertCdM2;
// A bright source saturates the screen locally (the power supply's current limit): an
// estimate, ten times the ABC's level.
const Float kScreenSaturationCdM2 = 10.0 * kAbcScreenCdM2;

// The halo (Thomas, Allison et al. 2005, "Physical modeling and characterization of the halo
// phenomenon in night vision goggles", SPIE 5800): photoelectrons that strike the plate's web
// between channels bounce back and land within about twice the cathode-to-plate gap, a spot of
// constant angular size around every bright point whatever its distance, which they model as a
// Gaussian. Craig, Macuda, Thomas, Allison & Jennings (2005, SPIE 5800) measured halos of
// 1 deg 48' (+-7') across with Gen III goggles; the Omni contracts' 0.70-1.25 mm on the tube are
// 1.5-2.7 deg through a 27 mm objective. Here the Gaussian's 2 sigma radius is that
// half-diameter, 0.9 deg: where a halo shows depends on how far it outshines the scene, so it
// spreads towards that size as the gain rises. The fraction of a source's light in its halo is
// an estimate: a few hundredths, enough to outshine the scene only near bright sources.
const Float kHaloDiameterDeg = 1.8;
const Float kHaloSigmaDeg = kHaloDiameterDeg / 4.0;
const Float kHaloFraction = 0.03;

// The tube's modulation transfer: a Gaussian MTF(f) = exp(-2 pi^2 sigma^2 f^2) through Omni
// IV-V's 0.38 at 25 lp/mm on the photocathode (sigma 8.9 um). The specification's 0.92 at
// 2.5 lp/mm, more loss at low frequency than a Gaussian has, is the veiling of the whole
// image, which the halo models for bright points only.
const Float kMtfReferenceLpPerMm = 25.0;
const Float kMtfAtReference = 0.38;
Float mtfSigmaRad() {
  Float sigmaMm = sqrt(-log(kMtfAtReference) / (2.0 * PI * PI)) / kMtfReferenceLpPerMm;
  return sigmaMm * 1e-3 / kObjectiveFocalLengthM;
}

// The photoelectrons' time on the screen: one frame of a 60 Hz display (the P43 phosphor decays
// to 10% in about 1 ms, so each frame shows its own electrons; the eye averages frames).
const Float kFrameSeconds = 1.0 / 60.0;
const Float kElectronCharge = 1.602176634e-19;

// Photocathode illuminance (lux) of a scene of luminance L (cd/m^2) through the objective
// (image illuminance of a distant scene on the axis: pi tau L / (4 N^2)). For a goggle's scene,
// L is the luminance of a 2856 K source of the same NVIS radiance: the NVIS radiance over the
// illuminant A's NVIS radiance per cd/m^2 (the response includes the photocathode's).
Float cathodeIlluminance(Float equivalentLuminance) {
  return PI * kObjectiveTransmittance * equivalentLuminance / (4.0 * kObjectiveFNumber * kObjectiveFNumber);
}

// Photoelectrons released in `seconds` from a patch of the photocathode of area `areaM2` at
// illuminance `lux` (of illuminant A): I = S E A.
Float photoelectrons(Float lux, Float areaM2, Float seconds) {
  return kCathodeSensitivityAPerLm * lux * areaM2 * seconds / kElectronCharge;
}

// The signal-to-noise ratio as the tube standards measure it: a 0.2 mm spot at 108 microlux
// (illuminant A) seen through a 10 Hz bandwidth (an integration of 1 / (2 x 10 Hz)); the
// plate's excess noise factor divides the photoelectrons' Poisson SNR.
Float goggleSignalToNoise(Float lux) {
  Float area = PI * 0.1e-3 * 0.1e-3;
  return sqrt(photoelectrons(lux, area, 0.05) / kExcessNoiseFactor);
}

// Without automatic brightness control: the screen's luminance gain (cd/m^2 per lux) at a
// fraction `fraction` (0-1] of the maximum. With it, render/passes/goggle/goggle_abc.frag solves for the gain
// that holds the screen's mean at kAbcScreenCdM2, at most kMaxLuminanceGain.
Float manualGain(Float fraction) { return clamp(fraction, 0.0, 1.0) * kMaxLuminanceGain; }

#endif
