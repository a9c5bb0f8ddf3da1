#include "io/atomic_file.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace softpack {

std::string temporary_path_for(const std::string& final_path) {
  const std::filesystem::path target(final_path);
  std::error_code ec;
  if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path(), ec);
  if (ec) throw InputError(fmt::format("{}: cannot create its folder: {}", final_path, ec.message()));
  return fmt::format("{}.tmp.{}", final_path, ::getpid());
}

void write_file_atomically(const std::string& path, const std::string& content) {
  const std::string tmp = temporary_path_for(path);
  // A full disk, a quota or an I/O error: one message, and the temporary goes.
  const auto failed = [&](const char* what, int error) {
    std::remove(tmp.c_str());
    throw InputError(fmt::format("{}: cannot {}: {}", path, what, std::strerror(error)));
  };
  std::FILE* out = std::fopen(tmp.c_str(), "wb");
  if (out == nullptr) failed("create the file", errno);
  const bool written = std::fwrite(content.data(), 1, content.size(), out) == content.size() && std::fflush(out) == 0;
  const int write_error = errno;
  if (std::fclose(out) != 0 || !written) failed("write the file", written ? errno : write_error);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) failed("rename it into place", errno);
}

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return in ? s.str() : std::string();
}

}  // namespace softpack
