#include "physics/common/sky_conditions.h"

namespace skyig::sky {

std::string_view toString(SkyModel model) {
  switch (model) {
    case SkyModel::Cie: return "cie";
    case SkyModel::Physical: return "physical";
    default: return "preetham";
  }
}

bool parseSkyModel(std::string_view text, SkyModel& model) {
  if (text == "preetham") model = SkyModel::Preetham;
  else if (text == "cie") model = SkyModel::Cie;
  else if (text == "physical") model = SkyModel::Physical;
  else return false;
  return true;
}

}  // namespace skyig::sky
