#include "io/hdf5_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>  // fmt::join
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "core/error.hpp"

namespace softpack::h5 {
namespace {

static_assert(std::is_same_v<hid_t, std::int64_t>, "File keeps its hid_t as std::int64_t");

// HDF5 prints its error stack to stderr by default; with the guard on, failures surface only as
// our exceptions. The previous handler is restored, so callers that want the dump keep it.
class QuietErrors {
 public:
  QuietErrors() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

// Owns one HDF5 identifier (dataset, group, type, space, property list, attribute).
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle(hid_t id, Closer close) : id_(id), close_(close) {}
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, -1)), close_(other.close_) {}
  Handle& operator=(Handle&&) = delete;
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  hid_t get() const { return id_; }
  explicit operator bool() const { return id_ >= 0; }

 private:
  hid_t id_;
  Closer close_;
};

// The most specific entry of HDF5's error stack, e.g. "truncated file: eof = ...".
std::string hdf5_reason() {
  std::string reason;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_UPWARD,
      [](unsigned n, const H5E_error2_t* e, void* out) -> herr_t {
        if (n == 0 && e->desc != nullptr) *static_cast<std::string*>(out) = e->desc;
        return 0;
      },
      &reason);
  return reason.empty() ? "HDF5 gave no reason" : reason;
}

// Library calls that cannot fail on valid arguments (property lists, types, spaces).
void must(herr_t status, const char* what) {
  if (status < 0) throw std::runtime_error(fmt::format("HDF5: {} failed ({})", what, hdf5_reason()));
}
Handle must(Handle h, const char* what) {
  if (!h) throw std::runtime_error(fmt::format("HDF5: {} failed ({})", what, hdf5_reason()));
  return h;
}

// Creation property list with object time stamps off: stamps would make every file unique.
Handle untimed(hid_t plist_class) {
  Handle p = must(Handle(H5Pcreate(plist_class), H5Pclose), "H5Pcreate");
  must(H5Pset_obj_track_times(p.get(), 0), "H5Pset_obj_track_times");
  return p;
}

Handle file_access(bool for_writing) {
  Handle fapl = must(Handle(H5Pcreate(H5P_FILE_ACCESS), H5Pclose), "H5Pcreate");
  // Pinned format: a newer library must not change the bytes we write. 1.8 is read everywhere.
  if (for_writing) must(H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V18, H5F_LIBVER_V18),
                        "H5Pset_libver_bounds");
  // Closing the file closes anything still open in it, so the file is complete on close.
  must(H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG), "H5Pset_fclose_degree");
#if H5_VERSION_GE(1, 10, 7)
  // Lock when the file system can; do not fail where it cannot (some network file systems).
  must(H5Pset_file_locking(fapl.get(), true, true), "H5Pset_file_locking");
#endif
  return fapl;
}

// "/a/b/c" and "a/b/c" -> {"a", "b", "c"}; "" and "/" -> {}. Empty components are refused.
std::vector<std::string> components(const std::string& file, const std::string& path) {
  std::vector<std::string> parts;
  std::size_t start = (!path.empty() && path[0] == '/') ? 1 : 0;
  while (start < path.size()) {
    const std::size_t slash = std::min(path.find('/', start), path.size());
    if (slash == start)
      throw std::invalid_argument(fmt::format("{}: '{}': empty path component", file, path));
    parts.push_back(path.substr(start, slash - start));
    start = slash + 1;
    if (slash + 1 == path.size())
      throw std::invalid_argument(fmt::format("{}: '{}': trailing '/'", file, path));
  }
  return parts;
}

bool exists_in(hid_t file, const std::string& file_path, const std::string& path) {
  std::string prefix;
  for (const std::string& part : components(file_path, path)) {
    prefix += "/" + part;
    // Negative when a component is not a group: then the path does not exist either.
    if (H5Lexists(file, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
  }
  return prefix.empty() || H5Oexists_by_name(file, prefix.c_str(), H5P_DEFAULT) > 0;
}

// Intermediate groups, made here rather than by H5Pset_create_intermediate_group: HDF5 stamps
// the groups it makes that way with the time even when the dataset is untimed.
void make_parent_groups(hid_t file, const std::string& file_path, const std::string& name) {
  const std::vector<std::string> parts = components(file_path, name);
  if (parts.empty()) throw std::invalid_argument(fmt::format("{}: empty dataset name", file_path));
  const Handle gcpl = untimed(H5P_GROUP_CREATE);
  std::string prefix;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    prefix += "/" + parts[i];
    const bool there = H5Lexists(file, prefix.c_str(), H5P_DEFAULT) > 0;
    const Handle g(there ? H5Gopen2(file, prefix.c_str(), H5P_DEFAULT)
                         : H5Gcreate2(file, prefix.c_str(), H5P_DEFAULT, gcpl.get(), H5P_DEFAULT),
                   H5Gclose);
    if (!g)
      throw std::runtime_error(fmt::format("{}: cannot write '{}': '{}' {}", file_path, name,
                                           prefix, there ? "is not a group" : hdf5_reason()));
  }
}

void write_dataset(hid_t file, const std::string& file_path, const std::string& name,
                   hid_t file_type, hid_t mem_type, hid_t space, const void* data) {
  if (exists_in(file, file_path, name))
    throw std::runtime_error(fmt::format("{}: dataset '{}' already exists", file_path, name));
  make_parent_groups(file, file_path, name);
  const Handle dcpl = untimed(H5P_DATASET_CREATE);
  const Handle ds(H5Dcreate2(file, name.c_str(), file_type, space, H5P_DEFAULT, dcpl.get(),
                             H5P_DEFAULT),
                  H5Dclose);
  if (!ds)
    throw std::runtime_error(
        fmt::format("{}: cannot create dataset '{}' ({})", file_path, name, hdf5_reason()));
  // H5Dwrite refuses a null buffer even for zero elements; an empty dataset needs no write.
  if (H5Sget_select_npoints(space) == 0) return;
  if (H5Dwrite(ds.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    throw std::runtime_error(
        fmt::format("{}: cannot write dataset '{}' ({})", file_path, name, hdf5_reason()));
}

Handle simple_space(const std::string& file_path, const std::string& name, std::size_t count,
                    std::vector<std::size_t> dims) {
  if (dims.empty()) dims = {count};
  std::size_t product = 1;
  for (std::size_t d : dims) product *= d;
  if (product != count || dims.size() > H5S_MAX_RANK)
    throw std::invalid_argument(fmt::format("{}: dataset '{}': shape ({}) does not hold {} values",
                                            file_path, name, fmt::join(dims, ", "), count));
  const std::vector<hsize_t> h(dims.begin(), dims.end());
  return must(Handle(H5Screate_simple(static_cast<int>(h.size()), h.data(), nullptr), H5Sclose),
              "H5Screate_simple");
}

Handle scalar_space() { return must(Handle(H5Screate(H5S_SCALAR), H5Sclose), "H5Screate"); }

// Variable-length UTF-8: h5py reads it as str, h5dump prints it.
Handle string_type() {
  Handle t = must(Handle(H5Tcopy(H5T_C_S1), H5Tclose), "H5Tcopy");
  must(H5Tset_size(t.get(), H5T_VARIABLE), "H5Tset_size");
  must(H5Tset_cset(t.get(), H5T_CSET_UTF8), "H5Tset_cset");
  return t;
}

// --- Reading: datasets and attributes alike -------------------------------------------------

bool is_attribute(hid_t obj) { return H5Iget_type(obj) == H5I_ATTR; }

Handle type_of(hid_t obj) {
  return must(Handle(is_attribute(obj) ? H5Aget_type(obj) : H5Dget_type(obj), H5Tclose),
              "get type");
}
Handle space_of(hid_t obj) {
  return must(Handle(is_attribute(obj) ? H5Aget_space(obj) : H5Dget_space(obj), H5Sclose),
              "get space");
}
void read_raw(hid_t obj, hid_t mem_type, void* buf, const std::string& what) {
  const herr_t status = is_attribute(obj)
                            ? H5Aread(obj, mem_type, buf)
                            : H5Dread(obj, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf);
  if (status < 0) throw InputError(fmt::format("{}: cannot read ({})", what, hdf5_reason()));
}

std::string describe(hid_t type) {
  const std::size_t bits = 8 * H5Tget_size(type);
  switch (H5Tget_class(type)) {
    case H5T_INTEGER:
      return fmt::format("{}-bit {} integers", bits,
                         H5Tget_sign(type) == H5T_SGN_NONE ? "unsigned" : "signed");
    case H5T_FLOAT: return fmt::format("{}-bit floating-point numbers", bits);
    case H5T_STRING: return "strings";
    case H5T_COMPOUND: return "a compound type";
    case H5T_ENUM: return "an enumeration";
    case H5T_ARRAY: return "an array type";
    case H5T_VLEN: return "a variable-length sequence";
    default: return "another HDF5 type";
  }
}

enum class Kind { real, integer, string };

void check_type(hid_t obj, Kind want, const std::string& what) {
  const Handle t = type_of(obj);
  const H5T_class_t c = H5Tget_class(t.get());
  const bool ok = want == Kind::real      ? c == H5T_FLOAT
                  : want == Kind::integer ? c == H5T_INTEGER &&
                                                (H5Tget_sign(t.get()) != H5T_SGN_NONE ||
                                                 H5Tget_size(t.get()) < 8)  // fits in int64
                                          : c == H5T_STRING;
  if (ok) return;
  const char* expected = want == Kind::real      ? "floating-point numbers"
                         : want == Kind::integer ? "integers that fit in 64-bit signed"
                                                 : "a string";
  throw InputError(fmt::format("{}: expected {}, found {}", what, expected, describe(t.get())));
}

// Shape of the data; {} for a scalar.
std::vector<std::size_t> shape_of(hid_t obj, const std::string& what) {
  const Handle s = space_of(obj);
  switch (H5Sget_simple_extent_type(s.get())) {
    case H5S_SCALAR: return {};
    case H5S_SIMPLE: {
      std::array<hsize_t, H5S_MAX_RANK> d{};
      const int rank = H5Sget_simple_extent_dims(s.get(), d.data(), nullptr);
      if (rank < 0) break;
      return std::vector<std::size_t>(d.begin(), d.begin() + rank);
    }
    case H5S_NULL: throw InputError(fmt::format("{}: holds no data (null dataspace)", what));
    default: break;
  }
  throw InputError(fmt::format("{}: unreadable dataspace ({})", what, hdf5_reason()));
}

std::string shape_text(const std::vector<std::size_t>& dims) {
  return dims.empty() ? "a scalar" : fmt::format("shape ({})", fmt::join(dims, ", "));
}

template <class T>
std::vector<T> read_array(hid_t obj, hid_t mem_type, Kind kind, std::vector<std::size_t>* dims,
                          const std::string& what) {
  check_type(obj, kind, what);
  const std::vector<std::size_t> shape = shape_of(obj, what);
  if (shape.empty() || (dims == nullptr && shape.size() != 1))
    throw InputError(fmt::format("{}: expected {}, found {}", what,
                                 dims == nullptr ? "a 1-D array" : "an array",
                                 shape_text(shape)));
  std::size_t count = 1;
  for (std::size_t d : shape) count *= d;
  std::vector<T> out(count);
  if (count > 0) read_raw(obj, mem_type, out.data(), what);
  if (dims != nullptr) *dims = shape;
  return out;
}

template <class T>
T read_scalar(hid_t obj, hid_t mem_type, Kind kind, const std::string& what) {
  check_type(obj, kind, what);
  const std::vector<std::size_t> shape = shape_of(obj, what);
  if (!shape.empty())
    throw InputError(fmt::format("{}: expected a scalar, found {}", what, shape_text(shape)));
  T value{};
  read_raw(obj, mem_type, &value, what);
  return value;
}

std::string read_string_from(hid_t obj, const std::string& what) {
  check_type(obj, Kind::string, what);
  const std::vector<std::size_t> shape = shape_of(obj, what);
  if (!shape.empty())
    throw InputError(fmt::format("{}: expected a scalar string, found {}", what,
                                 shape_text(shape)));
  const Handle file_type = type_of(obj);
  if (H5Tis_variable_str(file_type.get()) > 0) {
    const Handle mem_type = string_type();
    must(H5Tset_cset(mem_type.get(), H5Tget_cset(file_type.get())), "H5Tset_cset");
    char* p = nullptr;
    read_raw(obj, mem_type.get(), &p, what);
    std::string s = p != nullptr ? p : "";
    const Handle space = space_of(obj);
#if H5_VERSION_GE(1, 12, 0)
    H5Treclaim(mem_type.get(), space.get(), H5P_DEFAULT, &p);
#else
    H5Dvlen_reclaim(mem_type.get(), space.get(), H5P_DEFAULT, &p);
#endif
    return s;
  }
  // Fixed length: the stored bytes, cut at the padding.
  const Handle mem_type = must(Handle(H5Tcopy(file_type.get()), H5Tclose), "H5Tcopy");
  std::string s(H5Tget_size(file_type.get()), '\0');
  read_raw(obj, mem_type.get(), s.data(), what);
  if (H5Tget_strpad(file_type.get()) == H5T_STR_SPACEPAD) {
    s.erase(s.find_last_not_of(' ') + 1);
  } else {
    s.erase(std::min(s.find('\0'), s.size()));
  }
  return s;
}

std::string dataset_what(const std::string& file, const std::string& name) {
  return fmt::format("{}: dataset '{}'", file, name);
}
std::string attribute_what(const std::string& file, const std::string& obj,
                           const std::string& name) {
  return fmt::format("{}: attribute '{}' of '{}'", file, name, obj);
}

Handle open_dataset(hid_t file, const std::string& file_path, const std::string& name) {
  if (!exists_in(file, file_path, name))
    throw InputError(fmt::format("{}: no dataset '{}'", file_path, name));
  Handle ds(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!ds) throw InputError(fmt::format("{}: '{}' is not a dataset", file_path, name));
  return ds;
}

Handle open_attribute(hid_t file, const std::string& file_path, const std::string& obj,
                      const std::string& name) {
  if (!exists_in(file, file_path, obj))
    throw InputError(fmt::format("{}: no object '{}' (looking for its attribute '{}')",
                                 file_path, obj, name));
  if (H5Aexists_by_name(file, obj.c_str(), name.c_str(), H5P_DEFAULT) <= 0)
    throw InputError(fmt::format("{}: '{}' has no attribute '{}'", file_path, obj, name));
  Handle a(H5Aopen_by_name(file, obj.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
           H5Aclose);
  if (!a)
    throw InputError(fmt::format("{}: cannot open ({})", attribute_what(file_path, obj, name),
                                 hdf5_reason()));
  return a;
}

void write_attribute(hid_t file, const std::string& file_path, const std::string& obj,
                     const std::string& name, hid_t file_type, hid_t mem_type, const void* data) {
  if (!exists_in(file, file_path, obj))
    throw std::runtime_error(fmt::format("{}: cannot set attribute '{}': no object '{}'",
                                         file_path, name, obj));
  if (H5Aexists_by_name(file, obj.c_str(), name.c_str(), H5P_DEFAULT) > 0)
    must(H5Adelete_by_name(file, obj.c_str(), name.c_str(), H5P_DEFAULT), "H5Adelete_by_name");
  const Handle space = scalar_space();
  const Handle a(H5Acreate_by_name(file, obj.c_str(), name.c_str(), file_type, space.get(),
                                   H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                 H5Aclose);
  if (!a || H5Awrite(a.get(), mem_type, data) < 0)
    throw std::runtime_error(fmt::format("{}: cannot write attribute '{}' of '{}' ({})",
                                         file_path, name, obj, hdf5_reason()));
}

// HDF5 files start with this signature at offset 0, 512, 1024, ... (after a user block).
bool has_hdf5_signature(const std::string& path) {
  static constexpr char kSignature[8] = {'\211', 'H', 'D', 'F', '\r', '\n', '\032', '\n'};
  std::ifstream in(path, std::ios::binary);
  for (std::streamoff at = 0;; at = at == 0 ? 512 : 2 * at) {
    char head[8];
    if (!in.seekg(at) || !in.read(head, 8)) return false;
    if (std::memcmp(head, kSignature, 8) == 0) return true;
  }
}

}  // namespace

// --- File --------------------------------------------------------------------------------------

File File::create(const std::string& path) {
  const QuietErrors quiet;
  const Handle fcpl = untimed(H5P_FILE_CREATE);  // the root group's time stamps
  const Handle fapl = file_access(true);
  const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.get(), fapl.get());
  if (id < 0)
    throw InputError(fmt::format("{}: cannot create HDF5 file ({})", path, hdf5_reason()));
  return File(id, path);
}

File File::open(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(fmt::format("{}: no such file", path));
  if (std::filesystem::is_directory(path, ec))
    throw InputError(fmt::format("{}: is a directory, expected an HDF5 file", path));
  if (!std::ifstream(path, std::ios::binary))
    throw InputError(fmt::format("{}: cannot read: {}", path, std::strerror(errno)));
  const QuietErrors quiet;
  const Handle fapl = file_access(false);
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl.get());
  if (id < 0) {
    if (!has_hdf5_signature(path)) throw InputError(fmt::format("{}: not an HDF5 file", path));
    throw InputError(
        fmt::format("{}: truncated or corrupt HDF5 file ({})", path, hdf5_reason()));
  }
  return File(id, path);
}

File::File(File&& other) noexcept
    : id_(std::exchange(other.id_, -1)), path_(std::move(other.path_)) {}

File& File::operator=(File&& other) noexcept {
  if (this != &other) {
    if (id_ >= 0) {
      const QuietErrors quiet;
      H5Fclose(id_);
    }
    id_ = std::exchange(other.id_, -1);
    path_ = std::move(other.path_);
  }
  return *this;
}

File::~File() {
  if (id_ < 0) return;
  const QuietErrors quiet;
  H5Fclose(id_);
}

void File::close() {
  if (id_ < 0) return;
  const QuietErrors quiet;
  if (H5Fclose(std::exchange(id_, -1)) < 0)
    throw std::runtime_error(fmt::format("{}: cannot close HDF5 file ({})", path_, hdf5_reason()));
}

void File::write(const std::string& dataset, std::span<const double> values,
                 std::vector<std::size_t> dims) {
  const QuietErrors quiet;
  const Handle space = simple_space(path_, dataset, values.size(), std::move(dims));
  write_dataset(id_, path_, dataset, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, space.get(),
                values.data());
}

void File::write(const std::string& dataset, std::span<const std::int64_t> values,
                 std::vector<std::size_t> dims) {
  const QuietErrors quiet;
  const Handle space = simple_space(path_, dataset, values.size(), std::move(dims));
  write_dataset(id_, path_, dataset, H5T_STD_I64LE, H5T_NATIVE_INT64, space.get(),
                values.data());
}

void File::write_scalar(const std::string& dataset, double value) {
  const QuietErrors quiet;
  write_dataset(id_, path_, dataset, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, scalar_space().get(),
                &value);
}

void File::write_scalar(const std::string& dataset, std::int64_t value) {
  const QuietErrors quiet;
  write_dataset(id_, path_, dataset, H5T_STD_I64LE, H5T_NATIVE_INT64, scalar_space().get(),
                &value);
}

void File::write_string(const std::string& dataset, const std::string& value) {
  if (value.find('\0') != std::string::npos)
    throw std::invalid_argument(
        fmt::format("{}: dataset '{}': string holds a NUL character", path_, dataset));
  const QuietErrors quiet;
  const Handle type = string_type();
  const char* p = value.c_str();
  write_dataset(id_, path_, dataset, type.get(), type.get(), scalar_space().get(), &p);
}

void File::set_attribute(const std::string& object_path, const std::string& name,
                         double value) {
  const QuietErrors quiet;
  write_attribute(id_, path_, object_path, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

void File::set_attribute(const std::string& object_path, const std::string& name,
                         std::int64_t value) {
  const QuietErrors quiet;
  write_attribute(id_, path_, object_path, name, H5T_STD_I64LE, H5T_NATIVE_INT64, &value);
}

void File::set_attribute(const std::string& object_path, const std::string& name,
                         const std::string& value) {
  if (value.find('\0') != std::string::npos)
    throw std::invalid_argument(fmt::format("{}: attribute '{}' of '{}': string holds a NUL",
                                            path_, name, object_path));
  const QuietErrors quiet;
  const Handle type = string_type();
  const char* p = value.c_str();
  write_attribute(id_, path_, object_path, name, type.get(), type.get(), &p);
}

std::vector<double> File::read_doubles(const std::string& dataset,
                                       std::vector<std::size_t>* dims) const {
  const QuietErrors quiet;
  const Handle ds = open_dataset(id_, path_, dataset);
  return read_array<double>(ds.get(), H5T_NATIVE_DOUBLE, Kind::real, dims,
                            dataset_what(path_, dataset));
}

std::vector<std::int64_t> File::read_int64s(const std::string& dataset,
                                            std::vector<std::size_t>* dims) const {
  const QuietErrors quiet;
  const Handle ds = open_dataset(id_, path_, dataset);
  return read_array<std::int64_t>(ds.get(), H5T_NATIVE_INT64, Kind::integer, dims,
                                  dataset_what(path_, dataset));
}

double File::read_scalar_double(const std::string& dataset) const {
  const QuietErrors quiet;
  const Handle ds = open_dataset(id_, path_, dataset);
  return read_scalar<double>(ds.get(), H5T_NATIVE_DOUBLE, Kind::real,
                             dataset_what(path_, dataset));
}

std::int64_t File::read_scalar_int64(const std::string& dataset) const {
  const QuietErrors quiet;
  const Handle ds = open_dataset(id_, path_, dataset);
  return read_scalar<std::int64_t>(ds.get(), H5T_NATIVE_INT64, Kind::integer,
                                   dataset_what(path_, dataset));
}

std::string File::read_string(const std::string& dataset) const {
  const QuietErrors quiet;
  const Handle ds = open_dataset(id_, path_, dataset);
  return read_string_from(ds.get(), dataset_what(path_, dataset));
}

bool File::exists(const std::string& path) const {
  const QuietErrors quiet;
  return exists_in(id_, path_, path);
}

bool File::has_attribute(const std::string& object_path, const std::string& name) const {
  const QuietErrors quiet;
  return exists_in(id_, path_, object_path) &&
         H5Aexists_by_name(id_, object_path.c_str(), name.c_str(), H5P_DEFAULT) > 0;
}

std::string File::get_attribute_string(const std::string& object_path,
                                       const std::string& name) const {
  const QuietErrors quiet;
  const Handle a = open_attribute(id_, path_, object_path, name);
  return read_string_from(a.get(), attribute_what(path_, object_path, name));
}

double File::get_attribute_double(const std::string& object_path,
                                  const std::string& name) const {
  const QuietErrors quiet;
  const Handle a = open_attribute(id_, path_, object_path, name);
  return read_scalar<double>(a.get(), H5T_NATIVE_DOUBLE, Kind::real,
                             attribute_what(path_, object_path, name));
}

std::int64_t File::get_attribute_int64(const std::string& object_path,
                                       const std::string& name) const {
  const QuietErrors quiet;
  const Handle a = open_attribute(id_, path_, object_path, name);
  return read_scalar<std::int64_t>(a.get(), H5T_NATIVE_INT64, Kind::integer,
                                   attribute_what(path_, object_path, name));
}

// --- AtomicH5 ----------------------------------------------------------------------------------

namespace {
std::string temporary_for(const std::string& final_path) {
  const std::filesystem::path target(final_path);
  if (target.has_parent_path()) {
    std::error_code ec;
    std::filesystem::create_directories(target.parent_path(), ec);
    if (ec)
      throw InputError(fmt::format("{}: cannot create its directory: {}", final_path,
                                   ec.message()));
  }
  return fmt::format("{}.tmp.{}", final_path, ::getpid());
}
}  // namespace

AtomicH5::AtomicH5(const std::string& final_path)
    : final_(final_path), tmp_(temporary_for(final_path)), file_(File::create(tmp_)) {}

AtomicH5::~AtomicH5() {
  if (committed_) return;
  try {
    file_.close();
  } catch (...) {  // the temporary goes anyway
  }
  std::remove(tmp_.c_str());
}

void AtomicH5::commit() {
  if (committed_) throw std::logic_error(fmt::format("{}: committed twice", final_));
  file_.close();  // on failure the destructor removes the temporary
  if (std::rename(tmp_.c_str(), final_.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(tmp_.c_str());
    throw InputError(fmt::format("{}: cannot rename into place: {}", final_, why));
  }
  committed_ = true;
}

}  // namespace softpack::h5
