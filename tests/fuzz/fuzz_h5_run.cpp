// chainbreak.load's reader (app/h5_run_file.h): any bytes as an HDF5 file. Only h5::H5Error
// may escape (a file that is not HDF5, not a run, or damaged); a run that loads has datasets
// of the sizes its attributes say. The HDF5 library parses the file's structure itself, so a
// crash inside libhdf5 is a finding to report upstream, and to avoid by how we write: 1.10.8
// segfaulted in H5HG_read on a damaged variable-length string, so our strings are fixed
// length, in checksummed object headers (h5/h5_file.cpp). The seed: make_seeds.py with
// CHAINBREAK_EXE set.
#include <unistd.h>

#include <cstdio>
#include <string>

#include "app/h5_run_file.h"
#include "fuzz_support.h"
#include "h5/h5_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = "/tmp/fuzz_h5_run." + std::to_string(::getpid()) + ".h5";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  try {
    const cb::LoadedRun run = cb::load_h5_run(path);
    const auto n = static_cast<std::uint64_t>(run.description.beads);
    FUZZ_CHECK(run.tau.size() == run.rows && run.potential.size() == run.rows);
    FUZZ_CHECK(run.phi.size() == run.rows * n);
    FUZZ_CHECK(!run.description.psi || run.psi_dot.size() == run.rows * n);
  } catch (const cb::h5::H5Error&) {
  }
  return 0;
}
