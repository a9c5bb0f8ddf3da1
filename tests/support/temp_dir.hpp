// A temporary folder for one test, named after it and the process, created empty and removed
// with everything in it when the test ends.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <string>

namespace softpack::testing {

struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name)
      : path(std::filesystem::temp_directory_path() / ("softpack-" + name + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string operator/(const std::string& sub) const { return (path / sub).string(); }
};

}  // namespace softpack::testing
