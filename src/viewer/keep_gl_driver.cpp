#include "viewer/keep_gl_driver.h"

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CB_KEEP_GL_DRIVER 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)  // gcc's spelling
#define CB_KEEP_GL_DRIVER 1
#endif

#ifdef CB_KEEP_GL_DRIVER
#include <dlfcn.h>
#include <link.h>

#include <cstring>
#endif

namespace cb {

void keep_gl_driver_loaded() {
#ifdef CB_KEEP_GL_DRIVER
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void*) {
        if (info->dlpi_name && std::strstr(info->dlpi_name, "/dri/")) {
          // RTLD_NOLOAD: only a module that is already loaded; the extra reference is never
          // dropped, and RTLD_NODELETE keeps it mapped after the driver's own dlclose.
          dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
        }
        return 0;
      },
      nullptr);
#endif
}

}  // namespace cb
