// `run --resume`'s reader: a checkpoint file's bytes (checkpoint/checkpoint.h). Only
// CheckpointError may escape; a file that decodes encodes back to the very same bytes (every
// field is read exactly as written, nothing skipped or defaulted).
#include "checkpoint/checkpoint.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes = cb::fuzz::text_of(data, size);
  cb::Checkpoint c;
  try {
    c = cb::decode_checkpoint(bytes);
  } catch (const cb::CheckpointError&) {
    return 0;
  }
  FUZZ_CHECK(c.state.psi.size() == c.state.vel.size());
  FUZZ_CHECK(cb::encode_checkpoint(c) == bytes);
  return 0;
}
