#pragma once
// The eye's adaptation in time, driven by the host's clock so two nodes and a replay of one
// stream adapt alike. Pattanaik, Tumblin, Yee & Greenberg 2000 ("Time-dependent visual
// adaptation for fast realistic image display", SIGGRAPH 2000), section 3: cones and rods each
// adapt by a fast neural process (time constants 80 ms for cones, 150 ms for rods) and by slow
// pigment bleaching and regeneration (110 s for cones, 400 s for rods). skyig filters the
// logarithm of the adaptation level with the neural constant when light increases (light
// adaptation is fast) and with the pigment constant when it decreases (dark adaptation takes
// minutes); the state seen is the mesopic blend of the cone and rod levels.
//
// An eye adapted to A that looks at a scene whose own level is S sees it through the
// Naka-Rushton response R(L) = L^n / (L^n + A^n), n = 0.73 (Pattanaik et al. 2000, eq. 2):
// relative to an adapted eye the scene is darker by gain() when A > S (just after sunset into a
// dark cockpit view) and brighter, bleached, when A < S.
namespace skyig::sky::eye {

struct AdaptationTimes {
  double coneNeuralS = 0.08;
  double rodNeuralS = 0.15;
  double conePigmentS = 110.0;
  double rodPigmentS = 400.0;
};

class EyeAdaptation {
 public:
  explicit EyeAdaptation(AdaptationTimes times = {}) : times_(times) {}

  // Starts adapted to `sceneCdM2` at host time `timeS` (a new session, a scenario reset, a jump).
  void reset(double sceneCdM2, double timeS);
  // Advances to host time `timeS` towards the scene's steady level `sceneCdM2`. The first call,
  // and a step back in time (a restarted host), reset; no step changes nothing.
  void step(double sceneCdM2, double timeS);

  bool started() const { return started_; }
  // The adaptation level now, cd/m^2 (the mesopic blend of cones and rods).
  double level() const;
  // The display gain for the scene of level sceneCdM2 seen with this adaptation: R_A(S) / R_S(S)
  // of the Naka-Rushton response, in [0, 2].
  double gain(double sceneCdM2) const;
  double coneLevel() const;
  double rodLevel() const;

 private:
  AdaptationTimes times_;
  bool started_ = false;
  double timeS_ = 0.0;
  double coneLog_ = 0.0, rodLog_ = 0.0;  // log10 cd/m^2
  double sceneLog_ = 0.0;
};

// The weight of cone vision at luminance L (1 photopic, 0 scotopic): the mesopic blend of
// physics/eye/scotopic.glsl.
double coneWeight(double cdM2);

}  // namespace skyig::sky::eye
