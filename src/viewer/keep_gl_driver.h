// Under LeakSanitizer only: keeps the GL driver that GLFW's GLX context loaded mapped until
// the process ends.
//
// Why: at glfwTerminate, Mesa's GLX closes the display and dlclose()s its DRI driver
// (swrast_dri.so, llvmpipe). The driver's globals still point at ~250 strings it strdup'ed
// at start (its configuration), so nothing leaks while it is mapped; once unmapped, LSan's
// exit check finds those blocks unreferenced and reports 5.4 kB of "leaks" from an
// "<unknown module>", which no suppression can name. Measured: every viewer test under Xvfb
// failed so; with the driver kept mapped (LD_PRELOAD of swrast_dri.so) none reports a leak,
// even without tests/ci/lsan.supp. The ASan job must still catch our own leaks, so the fix
// keeps the driver's memory visible instead of silencing the report.
//
// A no-op in every build without AddressSanitizer (the shipped viewer unloads its driver as
// before).
#pragma once

namespace cb {

// Marks every loaded module under a ".../dri/" folder RTLD_NODELETE. Call once a GL context
// is current (the driver is loaded by then).
void keep_gl_driver_loaded();

}  // namespace cb
