#include "io/hdf5_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>  // fmt::join
#include <fcntl.h>
#include <hdf5.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <thread>
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
  // HDF5 answers "no" and "cannot tell" alike with a negative value when a component is not a
  // group; a failure under a group is a corrupt file, not an absent path.
  const auto corrupt = [&](const std::string& where, const std::string& reason) {
    return InputError(fmt::format("{}: cannot read '{}' ({}): corrupt file", file_path, where, reason));
  };
  const auto is_group = [&](const std::string& at) {
    return static_cast<bool>(Handle(H5Gopen2(file, at.empty() ? "/" : at.c_str(), H5P_DEFAULT), H5Gclose));
  };
  std::string prefix;
  for (const std::string& part : components(file_path, path)) {
    const std::string parent = prefix;
    prefix += "/" + part;
    const htri_t there = H5Lexists(file, prefix.c_str(), H5P_DEFAULT);
    if (there == 0) return false;
    if (there < 0) {
      const std::string reason = hdf5_reason();
      if (!is_group(parent)) return false;  // under a dataset or a dangling link: absent
      throw corrupt(prefix, reason);
    }
    // External and user-defined links would open other files named by this one: refused.
    H5L_info_t link{};
    if (H5Lget_info(file, prefix.c_str(), &link, H5P_DEFAULT) < 0) throw corrupt(prefix, hdf5_reason());
    if (link.type != H5L_TYPE_HARD && link.type != H5L_TYPE_SOFT)
      throw InputError(fmt::format("{}: '{}' is a link to another file; not followed", file_path, prefix));
  }
  if (prefix.empty()) return true;
  const htri_t object = H5Oexists_by_name(file, prefix.c_str(), H5P_DEFAULT);
  if (object < 0) throw corrupt(prefix, hdf5_reason());
  return object > 0;
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
//
// The file came from outside this process: every size is checked before it is used. libhdf5
// 1.10 trusts several of them (a variable-length string's heap object, a dataset's extent), so
// the checks below run before the library reads the data:
//   - a dataset cannot hold more values than the file has bytes (times the deflate ratio when
//     it is chunked), so a corrupt extent cannot make us allocate terabytes;
//   - numbers must be in the standard IEEE or two's-complement layouts (no custom precision or
//     offset for the library's generic converters to trip on);
//   - variable-length strings of datasets are read here from the global heap, whose collection
//     is checked first (libhdf5 copies the heap object by its own size into a buffer sized by
//     the string's length, and loops on some corrupt collections).

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

// The size of the file that holds `obj`, in bytes.
std::uint64_t file_size_of(hid_t obj, const std::string& what) {
  const Handle file(H5Iget_file_id(obj), H5Fclose);
  hsize_t size = 0;
  if (!file || H5Fget_filesize(file.get(), &size) < 0)
    throw InputError(fmt::format("{}: cannot get the file size ({})", what, hdf5_reason()));
  return size;
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

// Integers of 1, 2, 4 or 8 bytes using all their bits; IEEE binary32 or binary64.
bool standard_layout(hid_t t, H5T_class_t c) {
  if (c == H5T_INTEGER) {
    const std::size_t size = H5Tget_size(t);
    return (size == 1 || size == 2 || size == 4 || size == 8) && H5Tget_precision(t) == 8 * size &&
           H5Tget_offset(t) == 0;
  }
  if (c == H5T_FLOAT) {
    for (hid_t ieee : {H5T_IEEE_F32LE, H5T_IEEE_F32BE, H5T_IEEE_F64LE, H5T_IEEE_F64BE})
      if (H5Tequal(t, ieee) > 0) return true;
    return false;
  }
  return true;
}

void check_type(hid_t obj, Kind want, const std::string& what) {
  const Handle t = type_of(obj);
  const H5T_class_t c = H5Tget_class(t.get());
  const bool ok = want == Kind::real      ? c == H5T_FLOAT
                  : want == Kind::integer ? c == H5T_INTEGER &&
                                                (H5Tget_sign(t.get()) != H5T_SGN_NONE ||
                                                 H5Tget_size(t.get()) < 8)  // fits in int64
                                          : c == H5T_STRING;
  const char* expected = want == Kind::real      ? "floating-point numbers"
                         : want == Kind::integer ? "integers that fit in 64-bit signed"
                                                 : "a string";
  if (!ok)
    throw InputError(fmt::format("{}: expected {}, found {}", what, expected, describe(t.get())));
  if (!standard_layout(t.get(), c))
    throw InputError(fmt::format("{}: expected {} in a standard layout ({}), found {} of another layout",
                                 what, expected,
                                 want == Kind::real ? "IEEE 32- or 64-bit" : "8, 16, 32 or 64 bits",
                                 describe(t.get())));
}

// Shape of the data; {} for a scalar.
std::vector<std::size_t> shape_of(hid_t obj, const std::string& what) {
  const Handle s = space_of(obj);
  switch (H5Sget_simple_extent_type(s.get())) {
    case H5S_SCALAR: return {};
    case H5S_SIMPLE: {
      std::array<hsize_t, H5S_MAX_RANK> d{};
      const int rank = H5Sget_simple_extent_ndims(s.get());
      if (rank < 0 || rank > H5S_MAX_RANK || H5Sget_simple_extent_dims(s.get(), d.data(), nullptr) != rank)
        break;
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

// The number of values of `shape`, refused when the file cannot hold them: a corrupt extent
// must not make the reader allocate more than the file could expand to.
std::size_t checked_count(hid_t obj, const std::vector<std::size_t>& shape, const std::string& what) {
  // Deflate does not compress beyond 1032:1; no other filter of ours does better.
  constexpr std::uint64_t kMaxExpansion = 1032;
  std::uint64_t count = 1;
  for (std::size_t d : shape) {
    if (d != 0 && count > std::numeric_limits<std::uint64_t>::max() / d)
      throw InputError(fmt::format("{}: {} is too large (corrupt file?)", what, shape_text(shape)));
    count *= d;
  }
  if (count == 0) return 0;
  const Handle t = type_of(obj);
  const std::uint64_t value_bytes = std::max<std::uint64_t>(1, H5Tget_size(t.get()));
  const std::uint64_t file_bytes = file_size_of(obj, what);
  bool chunked = false;
  if (!is_attribute(obj)) {
    // Data in this file only: external raw files and virtual datasets name other files.
    const Handle dcpl(H5Dget_create_plist(obj), H5Pclose);
    const H5D_layout_t layout = dcpl ? H5Pget_layout(dcpl.get()) : H5D_LAYOUT_ERROR;
    if (layout != H5D_COMPACT && layout != H5D_CONTIGUOUS && layout != H5D_CHUNKED)
      throw InputError(fmt::format("{}: a dataset of another storage layout (virtual?) is not supported", what));
    if (H5Pget_external_count(dcpl.get()) != 0)
      throw InputError(fmt::format("{}: its data is stored in external files; not supported", what));
    chunked = layout == H5D_CHUNKED;
  }
  const std::uint64_t limit = chunked ? std::min(file_bytes, std::numeric_limits<std::uint64_t>::max() / kMaxExpansion) * kMaxExpansion
                                      : file_bytes;
  if (count > limit / value_bytes)
    throw InputError(fmt::format("{}: {} of {}-byte values is more than the file ({} bytes) can hold: "
                                 "truncated or corrupt file",
                                 what, shape_text(shape), value_bytes, file_bytes));
  return static_cast<std::size_t>(count);
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
  const std::size_t count = checked_count(obj, shape, what);
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

// Text read from a file must be UTF-8 (HDF5 stores ASCII or UTF-8) without NUL: it goes into
// messages, JSON and other files.
void check_utf8(const std::string& s, const std::string& what) {
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    std::size_t n = 0;
    char32_t cp = 0;
    if (c == 0) throw InputError(fmt::format("{}: the string holds a NUL character", what));
    if (c < 0x80) n = 1, cp = c;
    else if ((c & 0xE0) == 0xC0) n = 2, cp = c & 0x1F;
    else if ((c & 0xF0) == 0xE0) n = 3, cp = c & 0x0F;
    else if ((c & 0xF8) == 0xF0) n = 4, cp = c & 0x07;
    bool ok = n > 0 && i + n <= s.size();
    for (std::size_t k = 1; ok && k < n; ++k) {
      const auto b = static_cast<unsigned char>(s[i + k]);
      ok = (b & 0xC0) == 0x80;
      cp = (cp << 6) | (b & 0x3F);
    }
    static constexpr char32_t kSmallest[5] = {0, 0, 0x80, 0x800, 0x10000};
    ok = ok && cp >= kSmallest[n] && cp <= 0x10FFFF && !(cp >= 0xD800 && cp <= 0xDFFF);
    if (!ok)
      throw InputError(fmt::format("{}: the string is not UTF-8 text (byte {} is 0x{:02X})", what, i, c));
    i += n;
  }
}

// Little-endian unsigned integer of `n` bytes (HDF5's on-disk encoding of addresses, sizes).
std::uint64_t decode_le(const unsigned char* p, std::size_t n) {
  std::uint64_t v = 0;
  for (std::size_t k = n; k-- > 0;) v = (v << 8) | p[k];
  return v;
}

// A scalar variable-length string of a contiguous dataset, read from the file: the element
// (length, global heap collection address, object index), then the heap collection, checked
// against the file and the length before its object is taken.
std::string read_vlen_string_dataset(hid_t ds, const std::string& what) {
  const Handle dcpl(H5Dget_create_plist(ds), H5Pclose);
  if (!dcpl || H5Pget_layout(dcpl.get()) != H5D_CONTIGUOUS)
    throw InputError(fmt::format("{}: a variable-length string not stored contiguously (compact or chunked) "
                                 "is not supported",
                                 what));
  const Handle file(H5Iget_file_id(ds), H5Fclose);
  const Handle fcpl(file ? H5Fget_create_plist(file.get()) : -1, H5Pclose);
  std::size_t sizeof_addr = 0, sizeof_size = 0;
  hsize_t userblock = 0, file_bytes = 0;
  if (!fcpl || H5Pget_sizes(fcpl.get(), &sizeof_addr, &sizeof_size) < 0 ||
      H5Pget_userblock(fcpl.get(), &userblock) < 0 || H5Fget_filesize(file.get(), &file_bytes) < 0)
    throw InputError(fmt::format("{}: cannot read the file's layout ({})", what, hdf5_reason()));
  if (sizeof_addr < 2 || sizeof_addr > 8 || sizeof_size < 2 || sizeof_size > 8)
    throw InputError(fmt::format("{}: unsupported address sizes ({}, {} bytes)", what, sizeof_addr, sizeof_size));
  const haddr_t offset = H5Dget_offset(ds);
  if (offset == HADDR_UNDEF) throw InputError(fmt::format("{}: holds no data (never written)", what));

  std::vector<char> name(1024);
  const ssize_t name_length = H5Fget_name(file.get(), name.data(), name.size());
  if (name_length < 0 || static_cast<std::size_t>(name_length) >= name.size())
    throw InputError(fmt::format("{}: cannot get the file name ({})", what, hdf5_reason()));
  std::ifstream in(std::string(name.data(), static_cast<std::size_t>(name_length)), std::ios::binary);
  const auto read_at = [&](std::uint64_t at, std::size_t n, const char* part) {
    std::vector<unsigned char> bytes(n);
    if (at > file_bytes || n > file_bytes - at || !in.seekg(static_cast<std::streamoff>(at)) ||
        !in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(n)))
      throw InputError(fmt::format("{}: its {} lies beyond the end of the file: truncated or corrupt file",
                                   what, part));
    return bytes;
  };

  // The element: sequence length (4 bytes), heap collection address, object index (4 bytes).
  const std::vector<unsigned char> element = read_at(offset, 4 + sizeof_addr + 4, "data");
  const std::uint64_t length = decode_le(element.data(), 4);
  const std::uint64_t heap = decode_le(element.data() + 4, sizeof_addr);
  const std::uint64_t index = decode_le(element.data() + 4 + sizeof_addr, 4);
  if (length == 0) return "";
  const auto corrupt = [&](const std::string& why) {
    return InputError(fmt::format("{}: corrupt string storage ({}): truncated or corrupt file", what, why));
  };
  if (heap > file_bytes - userblock) throw corrupt("heap address beyond the end of the file");

  // The collection: "GCOL", version 1, 3 reserved bytes, its size; then objects of index (2),
  // reference count (2), 4 reserved bytes, size, data padded to 8 bytes; index 0 is free space.
  const std::size_t header = 8 + sizeof_size;
  const std::vector<unsigned char> head = read_at(userblock + heap, header, "string heap");
  if (std::memcmp(head.data(), "GCOL", 4) != 0 || head[4] != 1) throw corrupt("no heap collection at its address");
  const std::uint64_t collection = decode_le(head.data() + 8, sizeof_size);
  if (collection < header || collection > file_bytes - userblock - heap)
    throw corrupt("heap collection size beyond the end of the file");
  const std::vector<unsigned char> gcol = read_at(userblock + heap, static_cast<std::size_t>(collection), "string heap");
  const std::size_t object_header = 8 + sizeof_size;
  for (std::size_t at = header; at + object_header <= gcol.size();) {
    const std::uint64_t id = decode_le(&gcol[at], 2);
    const std::uint64_t size = decode_le(&gcol[at + 8], sizeof_size);
    if (id == 0) break;  // free space: the rest of the collection
    if (size > gcol.size() - at - object_header) throw corrupt("heap object beyond its collection");
    if (id == index) {
      if (size != length) throw corrupt(fmt::format("heap object of {} bytes for a string of {}", size, length));
      return std::string(reinterpret_cast<const char*>(&gcol[at + object_header]), static_cast<std::size_t>(size));
    }
    at += object_header + static_cast<std::size_t>((size + 7) / 8 * 8);
  }
  throw corrupt("heap object not found");
}

std::string read_string_from(hid_t obj, const std::string& what) {
  check_type(obj, Kind::string, what);
  const std::vector<std::size_t> shape = shape_of(obj, what);
  if (!shape.empty())
    throw InputError(fmt::format("{}: expected a scalar string, found {}", what,
                                 shape_text(shape)));
  const Handle file_type = type_of(obj);
  std::string s;
  if (H5Tis_variable_str(file_type.get()) > 0 && !is_attribute(obj)) {
    s = read_vlen_string_dataset(obj, what);
  } else if (H5Tis_variable_str(file_type.get()) > 0) {
    const Handle mem_type = string_type();
    must(H5Tset_cset(mem_type.get(), H5Tget_cset(file_type.get())), "H5Tset_cset");
    char* p = nullptr;
    read_raw(obj, mem_type.get(), &p, what);
    s = p != nullptr ? p : "";
    const Handle space = space_of(obj);
#if H5_VERSION_GE(1, 12, 0)
    H5Treclaim(mem_type.get(), space.get(), H5P_DEFAULT, &p);
#else
    H5Dvlen_reclaim(mem_type.get(), space.get(), H5P_DEFAULT, &p);
#endif
  } else {
    // Fixed length: the stored bytes, cut at the padding.
    const std::size_t size = H5Tget_size(file_type.get());
    if (size == 0 || size > file_size_of(obj, what))
      throw InputError(fmt::format("{}: a fixed-length string of {} bytes in a smaller file: truncated or corrupt file",
                                   what, size));
    const Handle mem_type = must(Handle(H5Tcopy(file_type.get()), H5Tclose), "H5Tcopy");
    s.assign(size, '\0');
    read_raw(obj, mem_type.get(), s.data(), what);
    if (H5Tget_strpad(file_type.get()) == H5T_STR_SPACEPAD) {
      s.erase(s.find_last_not_of(' ') + 1);
    } else {
      s.erase(std::min(s.find('\0'), s.size()));
    }
  }
  check_utf8(s, what);
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
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  for (std::uintmax_t at = 0; !ec && at + 8 <= size; at = at == 0 ? 512 : 2 * at) {
    char head[8];
    if (!in.seekg(static_cast<std::streamoff>(at)) || !in.read(head, 8)) return false;
    if (std::memcmp(head, kSignature, 8) == 0) return true;
  }
  return false;
}

// --- Preflight: libhdf5 crashes on some corrupt files -----------------------------------------
//
// libhdf5 1.10 is not hardened against corrupt files: a mangled local heap, B-tree or object
// header can make it dereference NULL or loop inside the library, where no check of ours can
// reach. Before File::open hands a file to the library, a child process walks the whole file with
// the calls the readers make (open every object, its type, dataspace, layout and attributes, read
// every numeric and fixed-length string dataset the size checks admit; variable-length strings
// are read by read_vlen_string_dataset, not by the library). A child that crashes or does not
// finish makes the file "corrupt" (InputError); errors it meets are left to the reader, which
// names them. The child runs no softpack code, so a bug of the readers still shows in the caller.

int preflight_seconds = 60;

}  // namespace
}  // namespace softpack::h5
// Present only in sanitizer builds (weak: null otherwise).
extern "C" void __sanitizer_set_death_callback(void (*callback)()) __attribute__((weak));
namespace softpack::h5 {
namespace {

herr_t preflight_attribute(hid_t obj, const char* name, const H5A_info_t*, void*) {
  const Handle a(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose);
  if (a) {
    const Handle t(H5Aget_type(a.get()), H5Tclose);
    const Handle sp(H5Aget_space(a.get()), H5Sclose);
    if (t) (void)H5Tget_class(t.get());
    if (sp) (void)H5Sget_simple_extent_npoints(sp.get());
  }
  return 0;
}

void preflight_dataset(hid_t ds, hsize_t file_bytes) {
  const Handle type(H5Dget_type(ds), H5Tclose);
  const Handle space(H5Dget_space(ds), H5Sclose);
  const Handle dcpl(H5Dget_create_plist(ds), H5Pclose);
  if (!type || !space || !dcpl) return;
  (void)H5Dget_offset(ds);
  (void)H5Dget_storage_size(ds);
  const H5D_layout_t layout = H5Pget_layout(dcpl.get());
  if ((layout != H5D_COMPACT && layout != H5D_CONTIGUOUS && layout != H5D_CHUNKED) ||
      H5Pget_external_count(dcpl.get()) != 0)
    return;
  const H5T_class_t c = H5Tget_class(type.get());
  const std::size_t size = H5Tget_size(type.get());
  const hssize_t n = H5Sget_simple_extent_npoints(space.get());
  if (n <= 0 || size == 0 || !standard_layout(type.get(), c)) return;
  const std::uint64_t limit = layout == H5D_CHUNKED ? file_bytes * 1032 : file_bytes;
  if (static_cast<std::uint64_t>(n) > limit / size) return;
  if (c == H5T_FLOAT) {
    std::vector<double> buf(static_cast<std::size_t>(n));
    (void)H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data());
  } else if (c == H5T_INTEGER) {
    std::vector<std::int64_t> buf(static_cast<std::size_t>(n));
    (void)H5Dread(ds, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data());
  } else if (c == H5T_STRING && H5Tis_variable_str(type.get()) == 0 &&
             static_cast<std::uint64_t>(n) <= file_bytes / size) {
    std::vector<char> buf(static_cast<std::size_t>(n) * size);
    (void)H5Dread(ds, type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data());
  }
}

struct PreflightWalk {
  hsize_t file_bytes = 0;
  std::size_t objects = 0;
};

herr_t preflight_link(hid_t group, const char* name, const H5L_info_t* info, void* data) {
  auto* walk = static_cast<PreflightWalk*>(data);
  if (++walk->objects > 100000) return 1;  // enough: stop the walk
  if (info->type != H5L_TYPE_HARD) return 0;
  const Handle obj(H5Oopen(group, name, H5P_DEFAULT), H5Oclose);
  if (!obj) return 0;
  hsize_t next = 0;
  (void)H5Aiterate2(obj.get(), H5_INDEX_NAME, H5_ITER_NATIVE, &next, preflight_attribute, nullptr);
  if (H5Iget_type(obj.get()) == H5I_DATASET) preflight_dataset(obj.get(), walk->file_bytes);
  return 0;
}

// In the child: the walk; its exit code does not matter, only that it ends.
[[noreturn]] void preflight_child(const std::string& path) {
  const int null = ::open("/dev/null", O_WRONLY);
  if (null >= 0) ::dup2(null, STDERR_FILENO);  // a crash report of a sanitizer build, say
  // A crash here is the answer, not an event for whatever watches the process: the default
  // actions (the parent sees the signal), and no sanitizer death callback (libFuzzer's would
  // save the input as a crash of the fuzz target, though the parent refuses it cleanly).
  for (const int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(sig, SIG_DFL);
  if (__sanitizer_set_death_callback != nullptr) __sanitizer_set_death_callback(nullptr);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  (void)H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG);
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl);
  if (file >= 0) {
    PreflightWalk walk;
    (void)H5Fget_filesize(file, &walk.file_bytes);
    hsize_t next = 0;
    (void)H5Aiterate2(file, H5_INDEX_NAME, H5_ITER_NATIVE, &next, preflight_attribute, nullptr);
    (void)H5Lvisit(file, H5_INDEX_NAME, H5_ITER_NATIVE, preflight_link, &walk);
    (void)H5Fclose(file);
  }
  ::_exit(0);
}

void preflight(const std::string& path) {
  std::fflush(nullptr);  // nothing buffered twice
  const pid_t child = ::fork();
  if (child < 0) return;  // cannot fork: go without
  if (child == 0) preflight_child(path);
  int status = 0;
  const auto start = std::chrono::steady_clock::now();
  auto pause = std::chrono::microseconds(100);
  for (;;) {
    const pid_t done = ::waitpid(child, &status, WNOHANG);
    if (done == child) break;
    if (done < 0 && errno != EINTR) return;
    if (std::chrono::steady_clock::now() - start > std::chrono::seconds(preflight_seconds)) {
      ::kill(child, SIGKILL);
      ::waitpid(child, &status, 0);
      throw InputError(fmt::format("{}: corrupt HDF5 file: the HDF5 library does not finish reading it ({} s)", path,
                                   preflight_seconds));
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(20000));
  }
  if (WIFSIGNALED(status))
    throw InputError(fmt::format("{}: corrupt HDF5 file: the HDF5 library crashes reading it ({})", path,
                                 strsignal(WTERMSIG(status))));
  // The child ends with _exit(0); anything else is a crash that a handler turned into an exit
  // (AddressSanitizer's SEGV handler exits with 1, for instance).
  if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
    throw InputError(fmt::format("{}: corrupt HDF5 file: the HDF5 library crashes reading it (exit status {})", path,
                                 WEXITSTATUS(status)));
}

}  // namespace

void set_preflight_seconds(int seconds) { preflight_seconds = std::max(1, seconds); }

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
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(fmt::format("{}: is not a regular file (a device or a pipe?), expected an HDF5 file", path));
  if (!std::ifstream(path, std::ios::binary))
    throw InputError(fmt::format("{}: cannot read: {}", path, std::strerror(errno)));
  preflight(path);
  const QuietErrors quiet;
  const Handle fapl = file_access(false);
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl.get());
  if (id < 0) {
    if (!has_hdf5_signature(path)) throw InputError(fmt::format("{}: not an HDF5 file", path));
    const std::string reason = hdf5_reason();
    unsigned long long eof = 0, base = 0, stored = 0;
    if (std::sscanf(reason.c_str(), "truncated file: eof = %llu, sblock->base_addr = %llu, stored_eof = %llu", &eof,
                    &base, &stored) == 3)
      throw InputError(fmt::format("{}: truncated or corrupt HDF5 file: it has {} bytes, its superblock says {} "
                                   "(an interrupted write or copy?)",
                                   path, eof, base + stored));
    throw InputError(fmt::format("{}: truncated or corrupt HDF5 file ({})", path, reason));
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
