// stb_truetype's code for the page. The program links it from Debian's compiled libstb, which
// has no WebAssembly build; the page compiles the same library from Debian's header
// (libstb-dev), the one way stb ships its code.
#define STB_TRUETYPE_IMPLEMENTATION
#include <stb_truetype.h>
