#pragma once
// The night may not include what is built from it.
#include "sky/state.h"
