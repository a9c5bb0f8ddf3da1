// HDF5 result files (io/hdf5_file.hpp): creating, opening and closing them, and the write path.
// Reading is io/hdf5_read.cpp; the workarounds for libhdf5 bugs are io/hdf5_quarantine.cpp.
#include "io/hdf5_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>  // fmt::join

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "core/error.hpp"
#include "io/hdf5_detail.hpp"

namespace softpack::h5 {
using detail::Handle;
using detail::components;
using detail::exists_in;
using detail::hdf5_reason;
using detail::must;
using detail::QuietErrors;

namespace detail {

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

void must(herr_t status, const char* what) {
  if (status < 0) throw std::runtime_error(fmt::format("HDF5: {} failed ({})", what, hdf5_reason()));
}
Handle must(Handle h, const char* what) {
  if (!h) throw std::runtime_error(fmt::format("HDF5: {} failed ({})", what, hdf5_reason()));
  return h;
}

}  // namespace detail

namespace {

// The errno of the operating system's refusal that HDF5's error stack reports ("errno = 28"), 0
// when it names none.
int os_errno() {
  int found = 0;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_UPWARD,
      [](unsigned, const H5E_error2_t* e, void* out) -> herr_t {
        int& n = *static_cast<int*>(out);
        if (n == 0 && e->desc != nullptr) {
          if (const char* at = std::strstr(e->desc, "errno = ")) n = std::atoi(at + 8);
        }
        return 0;
      },
      &found);
  return found;
}

// A write that failed: when the operating system refused it (a full disk, a quota, no
// permission, a folder that went away), one line for the user, InputError (exit 2); anything
// else is a bug, std::runtime_error. Call it right after the failing HDF5 call.
[[noreturn]] void write_failed(const std::string& file, const std::string& what) {
  if (const int e = os_errno(); e != 0)
    throw InputError(fmt::format("{}: cannot {}: {}", file, what, std::strerror(e)));
  throw std::runtime_error(fmt::format("{}: cannot {} ({})", file, what, hdf5_reason()));
}

// libhdf5 closes what is still open at exit (an atexit handler); after a failed write or a
// corrupt file it cannot, and says "infinite loop closing library" or crashes (SIGSEGV in
// H5F__close_cb on a full disk). Every file is closed by this layer (File, AtomicH5) before
// the executables exit, so the handler is not installed: it must be said before any other call.
[[maybe_unused]] const bool kNoAtexit = H5dont_atexit() >= 0;

static_assert(std::is_same_v<hid_t, std::int64_t>, "File keeps its hid_t as std::int64_t");

// Creation property list with object time stamps off: stamps would make every file unique.
// Links and attributes stay in the object header ("compact"), never in the fractal heaps of
// dense storage: the header is one checksummed block, and libhdf5 1.10.8 frees wild pointers
// iterating a dense group whose heap is damaged (free(): invalid pointer in
// H5G__link_release_table, h5py included; tests/faults/test_bit_flips.sh).
constexpr unsigned kMaxCompact = 4096;

Handle untimed(hid_t plist_class) {
  Handle p = must(Handle(H5Pcreate(plist_class), H5Pclose), "H5Pcreate");
  must(H5Pset_obj_track_times(p.get(), 0), "H5Pset_obj_track_times");
  must(H5Pset_attr_phase_change(p.get(), kMaxCompact, kMaxCompact - 1), "H5Pset_attr_phase_change");
  if (plist_class != H5P_DATASET_CREATE)  // groups and the root group
    must(H5Pset_link_phase_change(p.get(), kMaxCompact, kMaxCompact - 1), "H5Pset_link_phase_change");
  return p;
}

Handle file_access(bool for_writing) {
  Handle fapl = must(Handle(H5Pcreate(H5P_FILE_ACCESS), H5Pclose), "H5Pcreate");
  // Pinned format: a newer library must not change the bytes we write. The 1.10 format
  // checksums all its metadata (superblock, object headers, chunk indexes, heaps of links and
  // attributes); every reader since HDF5 1.10 (2016: h5py, h5dump, ParaView) reads it.
  if (for_writing) must(H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V110, H5F_LIBVER_V110),
                        "H5Pset_libver_bounds");
  // Closing the file closes anything still open in it, so the file is complete on close.
  must(H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG), "H5Pset_fclose_degree");
#if H5_VERSION_GE(1, 10, 7)
  // Lock when the file system can; do not fail where it cannot (some network file systems).
  must(H5Pset_file_locking(fapl.get(), true, true), "H5Pset_file_locking");
#endif
  return fapl;
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
    if (!g && there)
      throw std::runtime_error(fmt::format("{}: cannot write '{}': '{}' is not a group", file_path, name, prefix));
    if (!g) write_failed(file_path, fmt::format("create group '{}'", prefix));
  }
}

// Storage that a reader verifies. Arrays are chunked with HDF5's Fletcher-32 filter, which every
// read checks (H5Pset_edc_check is on by default, in h5py and h5dump too); one chunk per dataset
// up to kChunkBytes, so the chunk index is the single address in the (checksummed) object header.
// Scalars, strings and empty arrays are compact: their bytes are inside the object header, under
// its checksum. A flipped bit anywhere in a file is then an error on read (tests/faults).
constexpr hsize_t kChunkBytes = hsize_t{64} << 20;
constexpr std::size_t kCompactBytes = 48 * 1024;  // the object header holds at most 64 KiB

Handle checksummed_storage(hid_t type, hid_t space) {
  Handle dcpl = untimed(H5P_DATASET_CREATE);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> chunk(static_cast<std::size_t>(std::max(rank, 0)));
  if (rank > 0) H5Sget_simple_extent_dims(space, chunk.data(), nullptr);
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  if (rank == 0 || count == 0) {  // a number, or a string of at most kCompactBytes (write_string)
    must(H5Pset_layout(dcpl.get(), H5D_COMPACT), "H5Pset_layout");
    return dcpl;
  }
  // Rows of the first dimension per chunk: all of them unless the chunk would pass kChunkBytes.
  const hsize_t row_bytes = static_cast<hsize_t>(count) / chunk[0] * H5Tget_size(type);
  chunk[0] = std::clamp<hsize_t>(kChunkBytes / std::max<hsize_t>(row_bytes, 1), 1, chunk[0]);
  must(H5Pset_chunk(dcpl.get(), rank, chunk.data()), "H5Pset_chunk");
  must(H5Pset_fletcher32(dcpl.get()), "H5Pset_fletcher32");
  return dcpl;
}

void write_dataset(hid_t file, const std::string& file_path, const std::string& name,
                   hid_t file_type, hid_t mem_type, hid_t space, const void* data) {
  if (exists_in(file, file_path, name))
    throw std::runtime_error(fmt::format("{}: dataset '{}' already exists", file_path, name));
  make_parent_groups(file, file_path, name);
  const Handle dcpl = checksummed_storage(file_type, space);
  const Handle ds(H5Dcreate2(file, name.c_str(), file_type, space, H5P_DEFAULT, dcpl.get(),
                             H5P_DEFAULT),
                  H5Dclose);
  if (!ds) write_failed(file_path, fmt::format("create dataset '{}'", name));
  // H5Dwrite refuses a null buffer even for zero elements; an empty dataset needs no write.
  if (H5Sget_select_npoints(space) == 0) return;
  if (H5Dwrite(ds.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    write_failed(file_path, fmt::format("write dataset '{}'", name));
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

// Fixed-length UTF-8 of exactly the text's bytes (at least one), so the text is stored in the
// object header, under its checksum, not in the unchecksummed global heap of variable-length
// strings. h5py: ds.asstr()[()] is a str; h5dump prints it.
Handle string_type(std::size_t bytes) {
  Handle t = must(Handle(H5Tcopy(H5T_C_S1), H5Tclose), "H5Tcopy");
  must(H5Tset_size(t.get(), std::max<std::size_t>(bytes, 1)), "H5Tset_size");
  must(H5Tset_strpad(t.get(), H5T_STR_NULLPAD), "H5Tset_strpad");
  must(H5Tset_cset(t.get(), H5T_CSET_UTF8), "H5Tset_cset");
  return t;
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
    write_failed(file_path, fmt::format("write attribute '{}' of '{}'", name, obj));
}

// The version of the superblock (0 to 3), found at offset 0, 512, 1024, ... (after a user
// block); -1 when the file has no HDF5 signature.
int superblock_version(const std::string& path) {
  static constexpr char kSignature[8] = {'\211', 'H', 'D', 'F', '\r', '\n', '\032', '\n'};
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  for (std::uintmax_t at = 0; !ec && at + 8 <= size; at = at == 0 ? 512 : 2 * at) {
    char head[9] = {};  // a signature without its version byte: 0, let the library judge it
    if (!in.seekg(static_cast<std::streamoff>(at)) || !in.read(head, std::min<std::uintmax_t>(9, size - at)))
      return -1;
    if (std::memcmp(head, kSignature, 8) == 0) return static_cast<unsigned char>(head[8]);
  }
  return -1;
}

}  // namespace

// --- File --------------------------------------------------------------------------------------

File File::create(const std::string& path, const std::string& shown_as) {
  const QuietErrors quiet;
  const Handle fcpl = untimed(H5P_FILE_CREATE);  // the root group's time stamps
  const Handle fapl = file_access(true);
  const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.get(), fapl.get());
  if (id < 0) {
    const std::string& name = shown_as.empty() ? path : shown_as;
    if (const int e = os_errno(); e != 0)
      throw InputError(fmt::format("{}: cannot create the file: {}", name, std::strerror(e)));
    throw InputError(fmt::format("{}: cannot create HDF5 file ({})", name, hdf5_reason()));
  }
  return File(id, shown_as.empty() ? path : shown_as);
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
  const int superblock = superblock_version(path);
  if (superblock < 0) throw InputError(fmt::format("{}: not an HDF5 file", path));
  // libhdf5 walks the file in a child process first: it crashes or hangs on some damaged files
  // (io/hdf5_quarantine.cpp).
  detail::preflight(path);
  const QuietErrors quiet;
  const Handle fapl = file_access(false);
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl.get());
  if (id < 0) {
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
  if (H5Fclose(std::exchange(id_, -1)) < 0) write_failed(path_, "write the file (closing it)");
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
  if (value.size() > kCompactBytes)
    throw InputError(fmt::format("{}: dataset '{}': a text of {} bytes; a result file holds at most {} bytes of "
                                 "text per dataset (a configuration that long?)",
                                 path_, dataset, value.size(), kCompactBytes));
  const QuietErrors quiet;
  const Handle type = string_type(value.size());
  write_dataset(id_, path_, dataset, type.get(), type.get(), scalar_space().get(), value.c_str());
}

void File::set_attribute(const std::string& object_path, const std::string& name,
                         const std::string& value) {
  if (value.find('\0') != std::string::npos)
    throw std::invalid_argument(fmt::format("{}: attribute '{}' of '{}': string holds a NUL",
                                            path_, name, object_path));
  const QuietErrors quiet;
  const Handle type = string_type(value.size());
  write_attribute(id_, path_, object_path, name, type.get(), type.get(), value.c_str());
}

}  // namespace softpack::h5
