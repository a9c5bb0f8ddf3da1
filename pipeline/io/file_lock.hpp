// An advisory lock of its own file (flock(2)), so that processes that would make the same costly
// output make it once: the first makes it, the others wait and read it (formats/contents_file.hpp:
// the scenes of one packing, run side by side by make -j, each needing its nested contents). The
// kernel releases it when its holder ends, killed or not, so no stale lock outlives a run.
#pragma once
#include <functional>
#include <string>

namespace softpack {

class FileLock {
 public:
  /// Takes the lock of `path` (the file is created when missing, and left there), waiting while
  /// another holds it; `waiting` is called once, before the wait, when it must wait. A lock that
  /// cannot be had (a folder that cannot be written) is not taken: held() is false.
  explicit FileLock(const std::string& path, const std::function<void()>& waiting = {});
  ~FileLock();
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

  bool held() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

}  // namespace softpack
