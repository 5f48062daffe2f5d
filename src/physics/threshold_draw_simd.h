// What threshold_draw_avx2.cpp and threshold_draw_avx512.cpp include before their target
// pragma: the standard headers threshold_draw_lanes.inc needs, and two pragmas for it.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "physics/threshold_draw.h"

// See portable_math.cpp.
#ifdef __clang__
#pragma STDC FP_CONTRACT OFF
#endif
// portable_lanes.inc's functions take and return vectors; GCC warns that their ABI differs
// without the instruction set. They are those files' own (an anonymous namespace), never called
// from code built for another.
#ifndef __clang__
#pragma GCC diagnostic ignored "-Wpsabi"
#endif
