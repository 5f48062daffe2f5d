// An expr drive's muParser expression (make_forcing), evaluated at a few times.
// muParser is Debian's shared library, not instrumented: the fuzzer finds crashes and
// sanitizer reports on our side of it, and steers only by our own code's coverage.
#include "drive/drive.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cb::DriveDesc drive;
  drive.type = cb::DriveType::Expr;
  drive.expr = cb::fuzz::text_of(data, size);
  drive.t0 = 1.0;
  try {
    const cb::Forcing forcing = cb::make_forcing(drive);
    FUZZ_CHECK(forcing.f(0.5) == 0.0);  // before t0 there is no force
    for (const double tau : {1.0, 2.5, 100.0}) (void)forcing.f(tau);
  } catch (const cb::DriveError&) {
  }
  return 0;
}
