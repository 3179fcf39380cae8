#pragma once
// What the sky depends on besides the sun: the model and the state of the air and ground.
#include <string>
#include <string_view>

namespace skyig::render {

enum class SkyModel { Preetham, Cie };

std::string_view toString(SkyModel model);
// "preetham" or "cie"; false for anything else.
bool parseSkyModel(std::string_view text, SkyModel& model);

struct SkyConditions {
  SkyModel model = SkyModel::Preetham;
  int cieType = 12;             // 1..15, for SkyModel::Cie
  double turbidity = 2.5;       // Preetham's T, [1.7, 10]
  double groundAlbedo = 0.2;    // Lambertian, [0, 1]
  double sunDistanceAu = 1.0;   // scales the solar illuminance by 1/d^2
};

}  // namespace skyig::render
