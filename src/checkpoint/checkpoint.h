// Checkpoint files: the complete state of a run (ChainState, the integrator's cursor in the
// drive, how far its outputs got) and what it was (version, scene hash, the command), so
// `run --resume` continues it bit for bit.
//
// Design note: a small binary file, little-endian fixed-width fields, one FNV-1a 64 checksum
// over everything after the header. The reader checks the magic, the length and the checksum
// before it parses a field, and every field against the bytes left, so a truncated, flipped or
// foreign file is refused with a message, never loaded (tests/fuzz/fuzz_checkpoint.cpp feeds it
// arbitrary bytes). Written beside its name, fsynced and renamed into place (StagedPath), so a
// crash or a full disk leaves the previous checkpoint whole.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "physics/chain.h"

namespace cb {

struct CheckpointError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Checkpoint {
  std::string version;               // chainbreak's (CHAINBREAK_VERSION)
  std::string scene_hash;            // scene/scene_hash.h of the scene path and overrides
  std::vector<std::string> command;  // the run's options, to resume it (app/run_checkpoint.cpp)
  ChainState state;
  std::uint64_t next_kick = 0, next_breakpoint = 0;  // Integrator::Cursor
  std::uint64_t csv_bytes = 0;  // the CSV's partial file up to here belongs to this state
  std::uint64_t h5_rows = 0;    // so do the rows of the HDF5 file's journal
};

// Encodes and decodes the file's bytes; decode throws CheckpointError ("what is wrong").
std::string encode_checkpoint(const Checkpoint& c);
Checkpoint decode_checkpoint(const std::string& bytes);

// Writes `path` atomically; throws OutputError (the previous file stays).
void write_checkpoint(const std::string& path, const Checkpoint& c);
// Reads and checks `path`; throws CheckpointError naming the file.
Checkpoint read_checkpoint(const std::string& path);

}  // namespace cb
