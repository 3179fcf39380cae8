#include "physics/eye/adaptation.h"

#include "physics/eye/eye_physics.h"

#include <algorithm>
#include <cmath>

namespace skyig::sky::eye {

namespace {

constexpr double kFloorLog = -6.0;  // below starlight: nothing changes for the eye
constexpr double kNakaRushtonN = 0.73;

double log10Level(double cdM2) { return std::max(std::log10(std::max(cdM2, 1e-30)), kFloorLog); }

// One exponential step of a log level towards `target` over dt: neural when brightening, pigment
// when darkening.
double approach(double current, double target, double dt, double neuralS, double pigmentS) {
  const double tau = target > current ? neuralS : pigmentS;
  return target + (current - target) * std::exp(-dt / tau);
}

}  // namespace

double coneWeight(double cdM2) { return shader::mesopicFactor(std::max(cdM2, 0.0)); }

void EyeAdaptation::reset(double sceneCdM2, double timeS) {
  started_ = true;
  timeS_ = timeS;
  coneLog_ = rodLog_ = sceneLog_ = log10Level(sceneCdM2);
}

void EyeAdaptation::step(double sceneCdM2, double timeS) {
  if (!started_ || !std::isfinite(timeS_)) return reset(sceneCdM2, timeS);
  sceneLog_ = log10Level(sceneCdM2);
  const double dt = timeS - timeS_;
  if (dt < 0.0) return reset(sceneCdM2, timeS);
  if (!(dt > 0.0)) return;
  coneLog_ = approach(coneLog_, sceneLog_, dt, times_.coneNeuralS, times_.conePigmentS);
  rodLog_ = approach(rodLog_, sceneLog_, dt, times_.rodNeuralS, times_.rodPigmentS);
  timeS_ = timeS;
}

double EyeAdaptation::coneLevel() const { return std::pow(10.0, coneLog_); }
double EyeAdaptation::rodLevel() const { return std::pow(10.0, rodLog_); }

double EyeAdaptation::level() const {
  const double w = coneWeight(std::pow(10.0, sceneLog_));
  return std::pow(10.0, w * coneLog_ + (1.0 - w) * rodLog_);
}

double EyeAdaptation::gain(double sceneCdM2) const {
  const double s = std::pow(10.0, log10Level(sceneCdM2) * kNakaRushtonN);
  const double a = std::pow(level(), kNakaRushtonN);
  // R_A(S) / R_S(S) = [S^n / (S^n + A^n)] / (1/2)
  return 2.0 * s / (s + a);
}

}  // namespace skyig::sky::eye
