// Reading HDF5 files that came from outside this process (io/hdf5_file.hpp): every failure is an
// InputError naming the file and the dataset, with the reason of HDF5's error stack,
// and every size read from the file is checked before it is used:
//   - a dataset cannot hold more values than the file has bytes (times the deflate ratio when it
//     is chunked), so a corrupt extent cannot make the reader allocate terabytes;
//   - numbers must be in the standard IEEE or two's-complement layouts (no custom precision or
//     offset for the library's generic converters to trip on);
//   - links to other files, external raw data and virtual datasets are refused (they would make
//     the library open files that this one names);
//   - text must be UTF-8 without NUL.
// Variable-length strings of datasets are the exception: libhdf5 1.10 crashes or hangs on some
// corrupt global heaps, so io/hdf5_quarantine.cpp reads them.
#include <fmt/format.h>
#include <fmt/ranges.h>  // fmt::join

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/error.hpp"
#include "io/hdf5_detail.hpp"
#include "io/hdf5_file.hpp"

namespace softpack::h5 {
using detail::Handle;
using detail::hdf5_reason;
using detail::QuietErrors;

namespace detail {

std::vector<std::string> components(const std::string& file, const std::string& path) {
  std::vector<std::string> parts;
  std::size_t start = (!path.empty() && path[0] == '/') ? 1 : 0;
  while (start < path.size()) {
    const std::size_t slash = std::min(path.find('/', start), path.size());
    if (slash == start) throw std::invalid_argument(fmt::format("{}: '{}': empty path component", file, path));
    parts.push_back(path.substr(start, slash - start));
    start = slash + 1;
    if (slash + 1 == path.size()) throw std::invalid_argument(fmt::format("{}: '{}': trailing '/'", file, path));
  }
  return parts;
}

bool damaged_metadata(const std::string& reason) {
  return reason.find("checksum") != std::string::npos || reason.find("version") != std::string::npos ||
         reason.find("signature") != std::string::npos;
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
  const auto is_dataset = [&](const std::string& at) {
    return !at.empty() && static_cast<bool>(Handle(H5Dopen2(file, at.c_str(), H5P_DEFAULT), H5Dclose));
  };
  std::string prefix;
  for (const std::string& part : components(file_path, path)) {
    const std::string parent = prefix;
    prefix += "/" + part;
    const htri_t there = H5Lexists(file, prefix.c_str(), H5P_DEFAULT);
    if (there == 0) return false;
    if (there < 0) {
      const std::string reason = hdf5_reason();
      // Under a dataset or a dangling link: absent. Under a group that cannot answer, or an
      // object that opens as neither (a header failing its checksum or version check): corrupt.
      if (detail::damaged_metadata(reason) || is_group(parent)) throw corrupt(prefix, reason);
      if (is_dataset(parent)) return false;
      if (!parent.empty() && H5Oexists_by_name(file, parent.c_str(), H5P_DEFAULT) == 0) return false;
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

bool standard_layout(hid_t t) {
  const H5T_class_t c = H5Tget_class(t);
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

}  // namespace detail

namespace {

// A type or dataspace the library cannot decode is a corrupt file.
Handle type_of(hid_t obj, const std::string& what) {
  Handle t(H5Dget_type(obj), H5Tclose);
  if (!t) throw InputError(fmt::format("{}: unreadable type ({}): corrupt file", what, hdf5_reason()));
  return t;
}
Handle space_of(hid_t obj, const std::string& what) {
  Handle s(H5Dget_space(obj), H5Sclose);
  if (!s) throw InputError(fmt::format("{}: unreadable dataspace ({}): corrupt file", what, hdf5_reason()));
  return s;
}
void read_raw(hid_t obj, hid_t mem_type, void* buf, const std::string& what) {
  if (H5Dread(obj, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf) < 0)
    throw InputError(fmt::format("{}: cannot read ({}): corrupt file", what, hdf5_reason()));
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
      return fmt::format("{}-bit {} integers", bits, H5Tget_sign(type) == H5T_SGN_NONE ? "unsigned" : "signed");
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
  const Handle t = type_of(obj, what);
  const H5T_class_t c = H5Tget_class(t.get());
  const bool ok = want == Kind::real      ? c == H5T_FLOAT
                  : want == Kind::integer ? c == H5T_INTEGER && (H5Tget_sign(t.get()) != H5T_SGN_NONE ||
                                                                 H5Tget_size(t.get()) < 8)  // fits in int64
                                          : c == H5T_STRING;
  const char* expected = want == Kind::real      ? "floating-point numbers"
                         : want == Kind::integer ? "integers that fit in 64-bit signed"
                                                 : "a string";
  if (!ok) throw InputError(fmt::format("{}: expected {}, found {}", what, expected, describe(t.get())));
  if (!detail::standard_layout(t.get()))
    throw InputError(fmt::format("{}: expected {} in a standard layout ({}), found {} of another layout", what,
                                 expected, want == Kind::real ? "IEEE 32- or 64-bit" : "8, 16, 32 or 64 bits",
                                 describe(t.get())));
}

// Shape of the data; {} for a scalar.
std::vector<std::size_t> shape_of(hid_t obj, const std::string& what) {
  const Handle s = space_of(obj, what);
  switch (H5Sget_simple_extent_type(s.get())) {
    case H5S_SCALAR: return {};
    case H5S_SIMPLE: {
      std::array<hsize_t, H5S_MAX_RANK> d{};
      const int rank = H5Sget_simple_extent_ndims(s.get());
      if (rank < 0 || rank > H5S_MAX_RANK || H5Sget_simple_extent_dims(s.get(), d.data(), nullptr) != rank) break;
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
  constexpr std::uint64_t kMaxExpansion = 1032;  // deflate's best ratio; no other filter does better
  std::uint64_t count = 1;
  for (std::size_t d : shape) {
    if (d != 0 && count > std::numeric_limits<std::uint64_t>::max() / d)
      throw InputError(fmt::format("{}: {} is too large (corrupt file?)", what, shape_text(shape)));
    count *= d;
  }
  if (count == 0) return 0;
  const std::uint64_t value_bytes = std::max<std::size_t>(1, H5Tget_size(type_of(obj, what).get()));
  const std::uint64_t file_bytes = file_size_of(obj, what);
  // Data in this file only: external raw files and virtual datasets name other files.
  const Handle dcpl(H5Dget_create_plist(obj), H5Pclose);
  const H5D_layout_t layout = dcpl ? H5Pget_layout(dcpl.get()) : H5D_LAYOUT_ERROR;
  if (layout != H5D_COMPACT && layout != H5D_CONTIGUOUS && layout != H5D_CHUNKED)
    throw InputError(fmt::format("{}: a dataset of another storage layout (virtual?) is not supported", what));
  if (H5Pget_external_count(dcpl.get()) != 0)
    throw InputError(fmt::format("{}: its data is stored in external files; not supported", what));
  const bool chunked = layout == H5D_CHUNKED;
  const std::uint64_t limit =
      chunked ? std::min(file_bytes, std::numeric_limits<std::uint64_t>::max() / kMaxExpansion) * kMaxExpansion
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
    throw InputError(fmt::format("{}: expected {}, found {}", what, dims == nullptr ? "a 1-D array" : "an array",
                                 shape_text(shape)));
  std::vector<T> out(checked_count(obj, shape, what));
  if (!out.empty()) read_raw(obj, mem_type, out.data(), what);
  if (dims != nullptr) *dims = shape;
  return out;
}

template <class T>
T read_scalar(hid_t obj, hid_t mem_type, Kind kind, const std::string& what) {
  check_type(obj, kind, what);
  const std::vector<std::size_t> shape = shape_of(obj, what);
  if (!shape.empty()) throw InputError(fmt::format("{}: expected a scalar, found {}", what, shape_text(shape)));
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
    if (!ok) throw InputError(fmt::format("{}: the string is not UTF-8 text (byte {} is 0x{:02X})", what, i, c));
    i += n;
  }
}

std::string read_string_from(hid_t obj, const std::string& what) {
  check_type(obj, Kind::string, what);
  const std::vector<std::size_t> shape = shape_of(obj, what);
  if (!shape.empty())
    throw InputError(fmt::format("{}: expected a scalar string, found {}", what, shape_text(shape)));
  const Handle file_type = type_of(obj, what);
  std::string s;
  if (H5Tis_variable_str(file_type.get()) > 0 && detail::kQuarantine) {
    s = detail::read_vlen_string_dataset(obj, what);  // not H5Dread: see io/hdf5_quarantine.cpp
  } else if (H5Tis_variable_str(file_type.get()) > 0) {
    const Handle mem_type = detail::must(Handle(H5Tcopy(file_type.get()), H5Tclose), "H5Tcopy");
    char* p = nullptr;
    read_raw(obj, mem_type.get(), &p, what);
    s = p != nullptr ? p : "";
    H5free_memory(p);
  } else {
    // Fixed length: the stored bytes, cut at the padding.
    const std::size_t size = H5Tget_size(file_type.get());
    if (size == 0 || size > file_size_of(obj, what))
      throw InputError(fmt::format("{}: a fixed-length string of {} bytes in a smaller file: truncated or corrupt file",
                                   what, size));
    s.assign(size, '\0');
    read_raw(obj, file_type.get(), s.data(), what);
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

Handle open_dataset(hid_t file, const std::string& file_path, const std::string& name) {
  if (!detail::exists_in(file, file_path, name)) throw InputError(fmt::format("{}: no dataset '{}'", file_path, name));
  Handle ds(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!ds) {
    // A group is not a dataset; an object that opens as neither has a damaged header (which is
    // not opened again: libhdf5 1.10.8 leaks the header each time it fails its checks).
    const std::string reason = hdf5_reason();
    if (!detail::damaged_metadata(reason) && Handle(H5Gopen2(file, name.c_str(), H5P_DEFAULT), H5Gclose))
      throw InputError(fmt::format("{}: '{}' is a group, not a dataset", file_path, name));
    throw InputError(fmt::format("{}: cannot open '{}' ({}): corrupt file", file_path, name, reason));
  }
  return ds;
}

}  // namespace

std::vector<double> File::read_doubles(const std::string& dataset, std::vector<std::size_t>* dims) const {
  const QuietErrors quiet;
  return read_array<double>(open_dataset(id_, path_, dataset).get(), H5T_NATIVE_DOUBLE, Kind::real, dims,
                            dataset_what(path_, dataset));
}

std::vector<std::int64_t> File::read_int64s(const std::string& dataset, std::vector<std::size_t>* dims) const {
  const QuietErrors quiet;
  return read_array<std::int64_t>(open_dataset(id_, path_, dataset).get(), H5T_NATIVE_INT64, Kind::integer, dims,
                                  dataset_what(path_, dataset));
}

double File::read_scalar_double(const std::string& dataset) const {
  const QuietErrors quiet;
  return read_scalar<double>(open_dataset(id_, path_, dataset).get(), H5T_NATIVE_DOUBLE, Kind::real,
                             dataset_what(path_, dataset));
}

std::int64_t File::read_scalar_int64(const std::string& dataset) const {
  const QuietErrors quiet;
  return read_scalar<std::int64_t>(open_dataset(id_, path_, dataset).get(), H5T_NATIVE_INT64, Kind::integer,
                                   dataset_what(path_, dataset));
}

std::string File::read_string(const std::string& dataset) const {
  const QuietErrors quiet;
  return read_string_from(open_dataset(id_, path_, dataset).get(), dataset_what(path_, dataset));
}

bool File::exists(const std::string& path) const {
  const QuietErrors quiet;
  return detail::exists_in(id_, path_, path);
}

}  // namespace softpack::h5
