#pragma once
#include "physics/moon/moon.h"
