// Private to the HDF5 layer (io/hdf5_file.cpp, io/hdf5_read.cpp, io/hdf5_quarantine.cpp): owning
// handles, the quiet error guard and the reason HDF5's error stack gives. Includes hdf5.h, so no
// header outside pipeline/io/hdf5_* includes it.
#pragma once
#include <hdf5.h>

#include <string>
#include <utility>
#include <vector>

namespace softpack::h5::detail {

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

// Owns one HDF5 identifier (dataset, group, type, space, property list, attribute, file).
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

/// The most specific entry of HDF5's error stack, e.g. "truncated file: eof = ...".
std::string hdf5_reason();

/// Library calls that cannot fail on valid arguments (property lists, types, spaces): a failure
/// is a bug, std::runtime_error.
void must(herr_t status, const char* what);
Handle must(Handle h, const char* what);

/// "/a/b/c" and "a/b/c" -> {"a", "b", "c"}; "" and "/" -> {}. Empty components are refused
/// (std::invalid_argument: a bug of the caller, not of the file).
std::vector<std::string> components(const std::string& file, const std::string& path);
/// True when HDF5's reason says metadata failed its checksum, version or signature check: the
/// object is damaged, and is not probed again (libhdf5 1.10.8 leaks the header of each try).
bool damaged_metadata(const std::string& reason);
/// True when `path` names an object of `file`; InputError for a corrupt file or a link to another.
bool exists_in(hid_t file, const std::string& file_path, const std::string& path);
/// Integers of 1, 2, 4 or 8 bytes using all their bits; IEEE binary32 or binary64; any other class.
bool standard_layout(hid_t type);

// The workarounds for libhdf5 bugs, io/hdf5_quarantine.cpp. -DSOFTPACK_HDF5_TRUST_LIBRARY turns
// them off (the heap reader and the preflight): the test of whether they are still needed.
#ifdef SOFTPACK_HDF5_TRUST_LIBRARY
inline constexpr bool kQuarantine = false;
#else
inline constexpr bool kQuarantine = true;
#endif

/// A scalar variable-length string of a contiguous dataset, read from the global heap by the
/// layer, not by H5Dread. `what` names the file and dataset in messages.
std::string read_vlen_string_dataset(hid_t ds, const std::string& what);

/// Lets libhdf5 walk the file at `path` in a child process: InputError when the child crashes or
/// does not finish.
void preflight(const std::string& path);

}  // namespace softpack::h5::detail
