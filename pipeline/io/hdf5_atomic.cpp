// AtomicH5 (io/hdf5_file.hpp): an HDF5 output written under a temporary name and renamed into
// place on commit, so that an interrupted or failed run (a kill, a full disk) leaves no file.
#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5_file.hpp"

namespace softpack::h5 {

namespace {

// H5Fcreate can fail after it has made the file (a full disk: the superblock does not fit).
File create_or_remove(const std::string& tmp, const std::string& final_path) {
  try {
    return File::create(tmp, final_path);
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
}
}  // namespace

AtomicH5::AtomicH5(const std::string& final_path)
    : final_(final_path), tmp_(temporary_path_for(final_path)), file_(create_or_remove(tmp_, final_path)) {}

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
