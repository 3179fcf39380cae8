#pragma once
// The public API may not reach a socket header through what it includes.
#include "node/host/sender.h"
