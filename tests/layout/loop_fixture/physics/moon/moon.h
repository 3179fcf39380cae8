#pragma once
// A model may not include the state that is built from it.
#include "sky/state.h"
