// HDF5 result files: a small RAII layer over the HDF5 C API. Every failure becomes an exception
// naming the file and the dataset, and identical data gives byte-identical files, so make and
// the provenance checks can compare outputs by hash.
//
// Paths inside a file are "/"-separated ("stats/radial_profile/r"; a leading "/" is optional).
// Writers create the intermediate groups. Reading a missing, mistyped or wrongly shaped dataset
// throws InputError: the file came from outside this process.
//
// Determinism: object time stamps are off on the root group, every group and every dataset
// (HDF5 stamps them by default, including the groups H5Pset_create_intermediate_group makes,
// so this layer creates groups itself), and the on-disk format is pinned to the HDF5 1.10
// format (low and high bounds), so a newer library writes the same bytes.
//
// Integrity: every byte of a written file is under a checksum that the library verifies on
// read: metadata by the 1.10 format's own checksums, arrays by the Fletcher-32 filter, scalars
// and strings (fixed-length, compact) by the checksum of the object header that holds them. A
// flipped bit is an InputError naming the file and the dataset, in h5py and h5dump an error too.
//
// Atomicity: File::create writes in place. Results go through AtomicH5, which writes
// "<final>.tmp.<pid>" and renames on commit(), so an interrupted run leaves no file.
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace softpack::h5 {

/// An open HDF5 file (move-only). Not thread-safe: the serial HDF5 library is not.
class File {
 public:
  /// Creates (truncates) `path`; messages name it `shown_as` when given (the final name of a
  /// temporary). Throws InputError when it cannot be created, and a write or close that the
  /// operating system refuses (a full disk, no permission) is an InputError with its reason.
  static File create(const std::string& path, const std::string& shown_as = {});
  /// Opens `path` read-only. Throws InputError for a missing, unreadable, non-HDF5 or
  /// truncated file.
  static File open(const std::string& path);

  File(File&& other) noexcept;
  File& operator=(File&& other) noexcept;
  File(const File&) = delete;
  File& operator=(const File&) = delete;
  ~File();  ///< Closes quietly; call close() to see errors.

  const std::string& path() const { return path_; }
  /// Flushes and closes. Throws std::runtime_error on failure. Idempotent.
  void close();

  // Writing. `dims` empty means 1-D of values.size(); otherwise the product of `dims` must be
  // values.size() (row-major, e.g. {N, 3} for centres). A dataset is written once: writing an
  // existing name throws std::runtime_error.
  void write(const std::string& dataset, std::span<const double> values,
             std::vector<std::size_t> dims = {});
  void write(const std::string& dataset, std::span<const std::int64_t> values,
             std::vector<std::size_t> dims = {});
  void write_scalar(const std::string& dataset, double value);
  void write_scalar(const std::string& dataset, std::int64_t value);
  /// A scalar fixed-length UTF-8 string of at most 48 KiB (h5py: ds.asstr()[()] is a str);
  /// longer text is an InputError.
  void write_string(const std::string& dataset, const std::string& value);

  /// A text attribute (a unit, a description) of an existing group or dataset ("/" is the
  /// root); replaces an existing one. The engine writes attributes for people and other readers
  /// (h5py, h5dump) and never reads them back.
  void set_attribute(const std::string& object_path, const std::string& name, const std::string& value);

  // Reading. Without `dims` the dataset must be 1-D; with it any rank >= 1 is read row-major
  // and its shape returned. Floating-point data of any width reads as double; signed integers
  // (and unsigned ones narrower than 64 bits) read as int64.
  std::vector<double> read_doubles(const std::string& dataset,
                                   std::vector<std::size_t>* dims = nullptr) const;
  std::vector<std::int64_t> read_int64s(const std::string& dataset,
                                        std::vector<std::size_t>* dims = nullptr) const;
  double read_scalar_double(const std::string& dataset) const;
  std::int64_t read_scalar_int64(const std::string& dataset) const;
  /// A scalar string, variable- or fixed-length.
  std::string read_string(const std::string& dataset) const;

  /// True when `path` names a group or dataset ("" and "/" name the root).
  bool exists(const std::string& path) const;

 private:
  File(std::int64_t id, std::string path) : id_(id), path_(std::move(path)) {}

  std::int64_t id_ = -1;  // hid_t
  std::string path_;
};

/// File::open lets the library walk a file in a child process first when the library would
/// decode metadata of it without a checksum (libhdf5 1.10 crashes or loops on some such corrupt
/// files; io/hdf5_quarantine.cpp): a crash, or no end within this many seconds (default 60),
/// makes the file corrupt (InputError). The fuzz targets lower it.
void set_preflight_seconds(int seconds);

/// An HDF5 output written atomically: file() writes "<final>.tmp.<pid>"; commit() closes it
/// and renames it to `final`. Without commit() (an exception, an early return) the destructor
/// removes the temporary, so a failed run leaves no file.
class AtomicH5 {
 public:
  /// Creates the parent directories and the temporary. Throws InputError on failure.
  explicit AtomicH5(const std::string& final_path);
  ~AtomicH5();
  AtomicH5(const AtomicH5&) = delete;
  AtomicH5& operator=(const AtomicH5&) = delete;

  File& file() { return file_; }
  const std::string& temporary_path() const { return tmp_; }
  const std::string& final_path() const { return final_; }
  /// Closes the file and renames it into place. Throws on failure (and removes the temporary).
  void commit();

 private:
  std::string final_;
  std::string tmp_;
  File file_;
  bool committed_ = false;
};

}  // namespace softpack::h5
