// A run as an HDF5 file (`run --h5`, the Python module's Result.save and chainbreak.load), in
// the spirit of H5MD: self-describing datasets with units, the scene and the outcome as
// attributes. The layout (README "Long runs" has the table):
//
//   /h5md                      version = [1, 1]; /h5md/creator: name, version
//   /observables/{tau,f,energy,kinetic,potential}   rows        the CSV's first five columns
//   /chain/phi                 rows x N    the CSV's phi_1..phi_N
//   /chain/psi, /chain/psi_dot rows x N    with --psi (the CSV has psi only)
//   /  attributes              the scene (text, hash, parameters after overrides, overrides),
//                              solver, every, dt, version; at the end the steps, tau_end, breaks,
//                              energy books, SIMD path, exact first break
//
// Each value is the RunRow double the CSV prints, stored as IEEE binary64: bit for bit.
// Datasets are chunked in bands of rows (at most 1 MiB a chunk, 64 MiB a band held in memory),
// so one time's chain and one spring's history both read whole chunks, not the whole file.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/run_outputs.h"

namespace cb {

// Writes `path` (beside it, renamed into place by commit()). deflate 0: plain; 1-9: shuffle and
// deflate at that level (--h5-compress).
std::unique_ptr<RunFile> h5_run_file(const std::string& path, const RunDescription& description,
                                     int deflate);

// The same file for a resumable run (run --checkpoint; RunFile::sync records its rows): the
// rows go to a journal, "<dir>/.<name>.resume", which a checkpoint makes durable and a resumed
// run (resume_rows) cuts back to the checkpoint's rows, after SIGTERM or SIGKILL alike; the
// HDF5 file is written from it when the run ends, the same bytes as h5_run_file's. Throws
// OutputError when the journal is missing or shorter than the checkpoint says. Writing the
// file shows progress on stderr unless `quiet`.
std::unique_ptr<RunFile> resumable_h5_run_file(const std::string& path,
                                               const RunDescription& description, int deflate,
                                               std::optional<std::uint64_t> resume_rows,
                                               bool quiet);

// The shape of a dataset's chunks: rows along time, columns along the chain.
struct ChunkShape {
  std::uint64_t rows = 1, columns = 1;
};
// For `columns` values a row (0: a 1-D series) and at most `max_rows` rows: at most 1 MiB a
// chunk, bands of at most 64 MiB and 1/256 of the rows, sizes that pad the planned rows and
// the columns least.
ChunkShape chunk_shape(std::uint64_t columns, std::int64_t max_rows);

// A run read back from its HDF5 file.
struct LoadedRun {
  RunDescription description;
  RunOutcome outcome;
  std::string simd;  // the SIMD path's name ("" for the formula solvers)
  std::uint64_t rows = 0;
  std::vector<double> tau, f, energy, kinetic, potential, phi, psi, psi_dot;  // row-major
};
// Reads a file h5_run_file wrote; throws h5::H5Error or SceneError (what is wrong, and where).
LoadedRun load_h5_run(const std::string& path);

// Writes a LoadedRun (a Python Result) as h5_run_file would have.
void save_h5_run(const std::string& path, const LoadedRun& run, int deflate);

}  // namespace cb
