#include "h5/h5_file.h"

#include <hdf5.h>

#include <limits>
#include <memory>
#include <sstream>

namespace cb::h5 {

namespace {

static_assert(sizeof(hid_t) == sizeof(std::int64_t), "hid_t is kept as std::int64_t in the header");

// HDF5 prints its error stack to stderr by default; our messages say what went wrong instead.
void quiet_library() {
  static const bool once = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)once;
}

// An HDF5 handle closed by its own close function when it goes out of scope.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(Handle&& other) noexcept : id_(other.id_), close_(other.close_) { other.id_ = -1; }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle& operator=(Handle&&) = delete;
  hid_t get() const { return id_; }
  bool ok() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void require(bool ok, const std::string& file, const std::string& what) {
  if (!ok) throw H5Error(file + ": " + what);
}

// A UTF-8 string type; `size` 0: variable length (only for reading files of older versions).
Handle string_type(std::size_t size) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), size ? size : H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  // Exactly the text's bytes, no terminator stored (padded with NULs only when empty).
  if (size) H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
  return type;
}

constexpr unsigned kCompactAttributes = 64;

// A dataset's access: no chunk cache, bands of whole chunks go straight to the file (design
// note).
Handle dataset_access() {
  Handle dapl(H5Pcreate(H5P_DATASET_ACCESS), H5Pclose);
  H5Pset_chunk_cache(dapl.get(), 0, 0, H5D_CHUNK_CACHE_W0_DEFAULT);
  return dapl;
}

}  // namespace

Writer::Writer(const std::string& path) : path_(path) {
  quiet_library();
  // HDF5 1.10's format, the newest 1.10.8 writes: its chunk index for one unlimited dimension
  // (an extensible array) takes less room and time than 1.8's B-tree, and the superblock
  // (version 3), object headers (version 2), B-trees (version 2) and the extensible array
  // carry checksums, so a reader is told of damaged metadata instead of following it. HDF5
  // >= 1.10 (h5py, h5dump) reads it.
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V110, H5F_LIBVER_V110);
  // Attributes stay in their object's header (compact storage, up to 64 of them) rather than
  // moving to dense storage (a fractal heap and a B-tree of names) past HDF5's default of 8:
  // the root's 30-odd attributes then sit in checksummed headers, read in one piece.
  Handle fcpl(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
  H5Pset_attr_phase_change(fcpl.get(), kCompactAttributes, kCompactAttributes - 1);
  // No times in the object headers: two runs of the same scene write the same bytes.
  H5Pset_obj_track_times(fcpl.get(), 0);
  file_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.get(), fapl.get());
  require(file_ >= 0, path_, "cannot create the HDF5 file; choose a writable folder");
}

Writer::~Writer() {
  for (auto& d : datasets_)
    if (d.id >= 0) H5Dclose(d.id);
  if (file_ >= 0) H5Fclose(file_);
}

void Writer::group(const std::string& path) {
  // One group at a time (not H5Pset_create_intermediate_group, whose groups would take the
  // default properties: times in their headers).
  Handle gcpl(H5Pcreate(H5P_GROUP_CREATE), H5Pclose);
  H5Pset_obj_track_times(gcpl.get(), 0);
  for (std::size_t end = path.find('/', 1);; end = path.find('/', end + 1)) {
    const std::string prefix = path.substr(0, end);
    if (H5Lexists(file_, prefix.c_str(), H5P_DEFAULT) <= 0) {
      Handle g(H5Gcreate2(file_, prefix.c_str(), H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), H5Gclose);
      require(g.ok(), path_, "cannot create the group " + prefix);
    }
    if (end == std::string::npos) return;
  }
}

int Writer::dataset(const DatasetSpec& spec) {
  const int rank = spec.columns ? 2 : 1;
  const hsize_t dims[2] = {0, spec.columns};
  const hsize_t max_dims[2] = {H5S_UNLIMITED, spec.columns};
  const hsize_t chunk[2] = {spec.chunk_rows, spec.chunk_columns};
  Handle space(H5Screate_simple(rank, dims, max_dims), H5Sclose);
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_chunk(dcpl.get(), rank, chunk);
  H5Pset_fill_time(dcpl.get(), H5D_FILL_TIME_NEVER);  // every value is written once, by us
  if (spec.deflate > 0) {
    H5Pset_shuffle(dcpl.get());  // bytes of equal weight together: doubles deflate better
    H5Pset_deflate(dcpl.get(), static_cast<unsigned>(spec.deflate));
  }
  H5Pset_attr_phase_change(dcpl.get(), kCompactAttributes, kCompactAttributes - 1);
  H5Pset_obj_track_times(dcpl.get(), 0);
  Handle dapl = dataset_access();
  const std::size_t parent = spec.path.rfind('/');
  if (parent != std::string::npos && parent > 0) group(spec.path.substr(0, parent));
  const hid_t id =
      H5Dcreate2(file_, spec.path.c_str(), spec.integers ? H5T_STD_I64LE : H5T_IEEE_F64LE,
                 space.get(), H5P_DEFAULT, dcpl.get(), dapl.get());
  require(id >= 0, path_, "cannot create the dataset " + spec.path);
  datasets_.push_back({id, 0, spec.columns, spec.path});
  return static_cast<int>(datasets_.size() - 1);
}

void Writer::append(int index, const double* values, std::uint64_t rows) {
  append_values(index, H5T_NATIVE_DOUBLE, values, rows);
}

void Writer::append_ints(int index, const std::int64_t* values, std::uint64_t rows) {
  append_values(index, H5T_NATIVE_INT64, values, rows);
}

void Writer::append_values(int index, hid_t memory_type, const void* values, std::uint64_t rows) {
  if (rows == 0) return;
  Dataset& d = datasets_.at(static_cast<std::size_t>(index));
  const int rank = d.columns ? 2 : 1;
  const hsize_t extent[2] = {d.rows + rows, d.columns};
  require(H5Dset_extent(d.id, extent) >= 0, path_, "cannot extend " + d.path);
  Handle file_space(H5Dget_space(d.id), H5Sclose);
  const hsize_t start[2] = {d.rows, 0};
  const hsize_t count[2] = {rows, d.columns};
  H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr);
  Handle memory(H5Screate_simple(rank, count, nullptr), H5Sclose);
  require(H5Dwrite(d.id, memory_type, memory.get(), file_space.get(), H5P_DEFAULT, values) >= 0,
          path_, "writing " + d.path + " failed (disk full?)");
  d.rows += rows;
}

namespace {

void write_attr(hid_t file, const std::string& path, const std::string& object,
                const std::string& name, hid_t file_type, hid_t memory_type, hid_t space,
                const void* value) {
  Handle a(H5Acreate_by_name(file, object.c_str(), name.c_str(), file_type, space, H5P_DEFAULT,
                             H5P_DEFAULT, H5P_DEFAULT),
           H5Aclose);
  // An empty list has nothing to write (HDF5 refuses a write of no values).
  const bool empty = H5Sget_simple_extent_npoints(space) == 0;
  require(a.ok() && (empty || H5Awrite(a.get(), memory_type, value) >= 0), path,
          "cannot write the attribute " + name + " of " + object);
}

}  // namespace

void Writer::attr(const std::string& object, const std::string& name, const std::string& value) {
  // Fixed length, in the attribute's own object header: a variable-length string lives in
  // the global heap, which has no checksum, and libhdf5 1.10.8 segfaults (H5HG_read) on a
  // damaged one; the object header's checksum turns damage into an error instead. HDF5 wants
  // at least one byte: the empty string is one NUL of padding.
  const std::string text = value.empty() ? std::string(1, '\0') : value;
  Handle type = string_type(text.size());
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  write_attr(file_, path_, object, name, type.get(), type.get(), space.get(), text.data());
}

void Writer::attr(const std::string& object, const std::string& name, double value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  write_attr(file_, path_, object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, space.get(), &value);
}

void Writer::attr(const std::string& object, const std::string& name, std::int64_t value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  write_attr(file_, path_, object, name, H5T_STD_I64LE, H5T_NATIVE_INT64, space.get(), &value);
}

void Writer::attr(const std::string& object, const std::string& name,
                  const std::vector<double>& values) {
  const hsize_t n = values.size();
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  write_attr(file_, path_, object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, space.get(),
             values.data());
}

void Writer::attr(const std::string& object, const std::string& name,
                  const std::vector<std::int64_t>& values) {
  const hsize_t n = values.size();
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  write_attr(file_, path_, object, name, H5T_STD_I64LE, H5T_NATIVE_INT64, space.get(),
             values.data());
}

void Writer::close() {
  bool ok = true;
  for (auto& d : datasets_) {
    if (d.id >= 0 && H5Dclose(d.id) < 0) ok = false;
    d.id = -1;
  }
  if (file_ >= 0) {
    ok = H5Fflush(file_, H5F_SCOPE_GLOBAL) >= 0 && ok;
    ok = H5Fclose(file_) >= 0 && ok;
    file_ = -1;
  }
  require(ok, path_, "finishing the HDF5 file failed (disk full?)");
}

// ---- reading ----

Reader::Reader(const std::string& path) : path_(path) {
  quiet_library();
  require(H5Fis_hdf5(path.c_str()) > 0, path_, "not an HDF5 file (or it cannot be read)");
  file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  require(file_ >= 0, path_, "cannot open the HDF5 file (truncated or damaged?)");
}

Reader::~Reader() {
  if (file_ >= 0) H5Fclose(file_);
}

bool Reader::exists(const std::string& path) const {
  // H5Lexists needs every parent to exist: check the path one link at a time.
  std::string prefix;
  std::istringstream parts(path);
  for (std::string part; std::getline(parts, part, '/');) {
    if (part.empty()) continue;
    prefix += "/" + part;
    if (H5Lexists(file_, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
  }
  return !prefix.empty() && H5Oexists_by_name(file_, prefix.c_str(), H5P_DEFAULT) > 0;
}

namespace {

// The dataspace's dimensions (at most 2), refusing anything else.
std::vector<hsize_t> dims_of(hid_t space, const std::string& file, const std::string& what) {
  const int rank = H5Sget_simple_extent_ndims(space);
  require(rank >= 0 && rank <= 2, file, what + ": expected 1 or 2 dimensions");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0) H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  return dims;
}

bool numeric(hid_t type) {
  const H5T_class_t c = H5Tget_class(type);
  return c == H5T_FLOAT || c == H5T_INTEGER;
}

}  // namespace

std::vector<std::uint64_t> Reader::shape(const std::string& path) const {
  require(exists(path), path_, "no dataset " + path);
  Handle d(H5Dopen2(file_, path.c_str(), H5P_DEFAULT), H5Dclose);
  require(d.ok(), path_, path + " is not a dataset");
  Handle space(H5Dget_space(d.get()), H5Sclose);
  const auto dims = dims_of(space.get(), path_, path);
  require(!dims.empty(), path_, path + ": expected 1 or 2 dimensions");
  return {dims[0], dims.size() == 2 ? dims[1] : 0};
}

std::vector<double> Reader::doubles(const std::string& path) const {
  const auto s = shape(path);
  Handle d(H5Dopen2(file_, path.c_str(), H5P_DEFAULT), H5Dclose);
  Handle type(H5Dget_type(d.get()), H5Tclose);
  require(numeric(type.get()), path_, path + ": not a dataset of numbers");
  const std::uint64_t columns = s[1] ? s[1] : 1;
  // A damaged file may claim any size: refuse more than can be held.
  constexpr std::uint64_t kMaxValues = std::numeric_limits<std::uint64_t>::max() / 16;
  require(s[0] <= kMaxValues / columns, path_, path + ": impossible size");
  std::vector<double> values(s[0] * columns);
  if (!values.empty())
    require(H5Dread(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0,
            path_, "reading " + path + " failed (truncated or damaged file?)");
  return values;
}

std::vector<std::int64_t> Reader::ints(const std::string& path) const {
  const auto s = shape(path);
  require(s[1] == 0, path_, path + ": expected a series");
  Handle d(H5Dopen2(file_, path.c_str(), H5P_DEFAULT), H5Dclose);
  Handle type(H5Dget_type(d.get()), H5Tclose);
  require(numeric(type.get()), path_, path + ": not a dataset of numbers");
  require(s[0] <= std::numeric_limits<std::uint64_t>::max() / 16, path_,
          path + ": impossible size");
  std::vector<std::int64_t> values(s[0]);
  if (!values.empty())
    require(H5Dread(d.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0,
            path_, "reading " + path + " failed (truncated or damaged file?)");
  return values;
}

bool Reader::has_attr(const std::string& object, const std::string& name) const {
  return (object == "/" || exists(object)) &&
         H5Aexists_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT) > 0;
}

namespace {

// An open attribute with its type and dataspace, for the readers below.
struct OpenAttr {
  Handle attr, type, space;
};

OpenAttr open_attr(hid_t file, const std::string& path, const std::string& object,
                   const std::string& name) {
  Handle a(H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  require(a.ok(), path, "no attribute " + name + " on " + object);
  Handle type(H5Aget_type(a.get()), H5Tclose);
  Handle space(H5Aget_space(a.get()), H5Sclose);
  require(type.ok() && space.ok(), path, "the attribute " + name + " of " + object + " is damaged");
  return {std::move(a), std::move(type), std::move(space)};
}

std::uint64_t points_of(const OpenAttr& a, const std::string& file, const std::string& what) {
  if (H5Sget_simple_extent_type(a.space.get()) == H5S_NULL) return 0;
  const auto dims = dims_of(a.space.get(), file, what);
  require(dims.size() <= 1, file, what + ": expected a value or a list");
  return dims.empty() ? 1 : dims[0];
}

template <class T>
std::vector<T> read_numbers(hid_t file, const std::string& path, const std::string& object,
                            const std::string& name, hid_t memory_type) {
  const OpenAttr a = open_attr(file, path, object, name);
  const std::string what = "attribute " + name + " of " + object;
  require(numeric(a.type.get()), path, what + ": not numbers");
  std::vector<T> values(points_of(a, path, what));
  if (!values.empty())
    require(H5Aread(a.attr.get(), memory_type, values.data()) >= 0, path,
            "reading the " + what + " failed");
  return values;
}

}  // namespace

std::string Reader::string_attr(const std::string& object, const std::string& name) const {
  const OpenAttr a = open_attr(file_, path_, object, name);
  const std::string what = "attribute " + name + " of " + object;
  require(H5Tget_class(a.type.get()) == H5T_STRING && points_of(a, path_, what) == 1, path_,
          what + ": not a text");
  if (H5Tis_variable_str(a.type.get()) > 0) {
    Handle memory = string_type(0);
    char* text = nullptr;
    require(H5Aread(a.attr.get(), memory.get(), &text) >= 0, path_,
            "reading the " + what + " failed");
    std::string out = text ? text : "";
    H5free_memory(text);
    return out;
  }
  const std::size_t size = H5Tget_size(a.type.get());
  require(size > 0 && size < (1u << 30), path_, what + ": impossible size");
  std::string out(size, '\0');
  require(H5Aread(a.attr.get(), a.type.get(), out.data()) >= 0, path_,
          "reading the " + what + " failed");
  return out.substr(0, out.find('\0'));
}

double Reader::double_attr(const std::string& object, const std::string& name) const {
  const auto v = doubles_attr(object, name);
  require(v.size() == 1, path_, "attribute " + name + " of " + object + ": expected one number");
  return v[0];
}

std::int64_t Reader::int_attr(const std::string& object, const std::string& name) const {
  const auto v = ints_attr(object, name);
  require(v.size() == 1, path_, "attribute " + name + " of " + object + ": expected one number");
  return v[0];
}

std::vector<double> Reader::doubles_attr(const std::string& object, const std::string& name) const {
  return read_numbers<double>(file_, path_, object, name, H5T_NATIVE_DOUBLE);
}

std::vector<std::int64_t> Reader::ints_attr(const std::string& object,
                                            const std::string& name) const {
  return read_numbers<std::int64_t>(file_, path_, object, name, H5T_NATIVE_INT64);
}

}  // namespace cb::h5
