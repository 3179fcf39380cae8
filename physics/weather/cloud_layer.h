#pragma once
// What a cloud layer's type means and which layers are good (the data: physics/common/cloud_layer.h).
// The ten types of CIGI's Weather Control fall in three families of appearance (WMO International
// Cloud Atlas, 2017: the genera by their form): stratiform sheets (stratus, nimbostratus,
// altostratus, stratocumulus), heaped cumuliform clouds (cumulus, cumulonimbus) and thin high
// cirriform veils (cirrus, cirrostratus, cirrocumulus); altocumulus, a layer of heaped cloudlets,
// is drawn with the sheets.
#include "physics/common/cloud_layer.h"

#include <optional>
#include <string>
#include <string_view>

namespace skyig::weather {

enum class CloudFamily { Stratiform, Cumuliform, Cirriform };
CloudFamily familyOf(sky::CloudType type);

// "stratus", "cumulonimbus", ...: the CIGI names in lower case.
std::string_view toString(sky::CloudType type);
std::optional<sky::CloudType> parseCloudType(std::string_view name);
// CIGI's 4-bit Cloud Type: 1-10 a type; 0 (none) and 11-15 (other) none.
std::optional<sky::CloudType> cloudTypeOfCigi(int value);

// Throws std::invalid_argument naming the value when an enabled layer cannot be drawn: a
// non-finite number, a thickness not above 0, a coverage outside 0-100, a negative band, scud
// frequency or visibility, a severity outside 0-5, a wind outside 0-150 m/s. A disabled layer
// is always good.
void validate(const sky::CloudLayer& layer);

// A layer from "TYPE:BASE:THICKNESS[:COVERAGE[:WIND:FROM]]" (metres above the ground, percent;
// coverage 100 when not given; the wind that moves it in m/s and the direction it blows from in
// degrees from true north, calm when not given), as `render --cloud`, `host --cloud` and the
// host's weather script take it; throws std::invalid_argument naming the part that is wrong.
sky::CloudLayer parseCloudSpec(std::string_view spec);

// "stratus base 300 m, 400 m thick, 100 % cover" for the node's log.
std::string describe(const sky::CloudLayer& layer);

}  // namespace skyig::weather
