#pragma once
#include "sky/night/moon.h"
