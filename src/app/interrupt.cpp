// The interruption flag every long loop of the commands polls. Set by the CLI's signal
// handler (main.cpp) or by the Python module when Python sees Ctrl-C (src/python).
#include "app/commands.h"

namespace cb {
std::atomic<bool> g_interrupted{false};
}
