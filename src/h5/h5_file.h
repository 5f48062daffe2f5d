// HDF5 files of doubles, through the HDF5 C library (Debian libhdf5-dev): a writer of
// extendable chunked datasets and attributes, and a reader of what it writes. Knows nothing of
// chains or scenes: the run's layout is app/h5_run_file.cpp's.
//
// Design note: rows arrive one at a time but are written in bands of whole chunks (the caller
// buffers a band and appends it), and the chunk cache is off, so HDF5 writes each chunk once,
// straight from the caller's buffer, never reading it back. HDF5's own error printing is
// turned off; every failure becomes an H5Error naming the file and the object.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace cb::h5 {

struct H5Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One dataset of doubles, rows x columns (columns 0: a 1-D series of rows), extendable along
// the rows and chunked `chunk_rows` x `chunk_columns`.
struct DatasetSpec {
  std::string path;  // "/observables/tau"
  std::uint64_t columns = 0;
  std::uint64_t chunk_rows = 1, chunk_columns = 1;
  int deflate = 0;        // 0: none; 1-9: byte shuffle then deflate at that level
  bool integers = false;  // 64-bit integers instead of doubles (append_ints)
};

class Writer {
 public:
  // Creates or truncates the file.
  explicit Writer(const std::string& path);
  ~Writer();
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  void group(const std::string& path);
  // Creates an empty dataset; returns its handle for append().
  int dataset(const DatasetSpec& spec);
  // Appends `rows` rows (rows x columns doubles, row-major) at the end of dataset `id`.
  void append(int id, const double* values, std::uint64_t rows);
  void append_ints(int id, const std::int64_t* values, std::uint64_t rows);

  // Attributes on a group or dataset ("/" is the file). Strings are UTF-8, fixed length (the
  // text's bytes, NUL-padded; see h5_file.cpp for why not variable length).
  void attr(const std::string& object, const std::string& name, const std::string& value);
  void attr(const std::string& object, const std::string& name, double value);
  void attr(const std::string& object, const std::string& name, std::int64_t value);
  void attr(const std::string& object, const std::string& name, const std::vector<double>& values);
  void attr(const std::string& object, const std::string& name,
            const std::vector<std::int64_t>& values);

  // Flushes and closes the file; throws H5Error (e.g. disk full). The destructor closes
  // without checking.
  void close();

 private:
  void append_values(int id, std::int64_t memory_type, const void* values, std::uint64_t rows);
  struct Dataset {
    std::int64_t id = -1;
    std::uint64_t rows = 0, columns = 0;
    std::string path;
  };
  std::string path_;
  std::int64_t file_ = -1;
  std::vector<Dataset> datasets_;
};

class Reader {
 public:
  explicit Reader(const std::string& path);  // H5Error when it is not an HDF5 file
  ~Reader();
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  bool exists(const std::string& path) const;
  // Rows and columns of a dataset of doubles (columns 0 for a 1-D one).
  std::vector<std::uint64_t> shape(const std::string& path) const;
  std::vector<double> doubles(const std::string& path) const;  // the whole dataset, row-major
  std::vector<std::int64_t> ints(const std::string& path) const;

  bool has_attr(const std::string& object, const std::string& name) const;
  std::string string_attr(const std::string& object, const std::string& name) const;
  double double_attr(const std::string& object, const std::string& name) const;
  std::int64_t int_attr(const std::string& object, const std::string& name) const;
  std::vector<double> doubles_attr(const std::string& object, const std::string& name) const;
  std::vector<std::int64_t> ints_attr(const std::string& object, const std::string& name) const;

 private:
  std::string path_;
  std::int64_t file_ = -1;
};

}  // namespace cb::h5
