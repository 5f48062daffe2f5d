// The attribute locations the shaders use, shared by C++ and GLSL: the program prepends
// these as #defines to every shader in shaders/, so the two cannot drift apart.
#pragma once

namespace cb::shader {

inline constexpr int kCorner = 0;    // per-vertex corner of the unit quad
inline constexpr int kEnds = 1;      // quad: x0, y0, x1, y1
inline constexpr int kColor = 2;     // every program: RGBA
inline constexpr int kStyle = 3;     // quad: width, antialiasing margin
inline constexpr int kCenter = 4;    // disc: x, y, radius
inline constexpr int kPosition = 5;  // triangle: x, y
inline constexpr int kRect = 6;      // glyph: x, y, width, height
inline constexpr int kUv = 7;        // glyph: u0, v0, u1, v1

// The GLSL preamble: version and the locations above.
const char* preamble();

}  // namespace cb::shader
