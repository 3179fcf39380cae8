#pragma once
#include <glad/gl.h>
