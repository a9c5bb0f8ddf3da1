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
  // "<name>.tmp.<pid>", with <name> cut (at a UTF-8 character's start) so that the temporary's
  // name fits where the final one does: a legal name of 246-255 bytes was refused ("File name too
  // long") for its temporary's suffix. Still matched by *.tmp.* (the recipes' clean-up).
  const std::string suffix = fmt::format(".tmp.{}", ::getpid());
  std::string name = target.filename().string();
  constexpr std::size_t kNameMax = 255;  // bytes of one name on Linux's file systems (NAME_MAX)
  if (name.size() > kNameMax)  // refused before anything is computed, as the system would at the end
    throw InputError(fmt::format("{}: File name too long (its last part has {} bytes; allowed: at most {})", final_path,
                                 name.size(), kNameMax));
  if (name.size() + suffix.size() > kNameMax) {
    std::size_t keep = kNameMax > suffix.size() ? kNameMax - suffix.size() : 0;
    while (keep > 0 && (static_cast<unsigned char>(name[keep]) & 0xC0) == 0x80) --keep;
    name.resize(keep);
  }
  return (target.parent_path() / (name + suffix)).string();
}

namespace {

// Writes `content` to the temporary `tmp` of `path`; on failure removes it and throws InputError
// (a full disk, a quota or an I/O error: one message, naming the final path).
void write_temporary(const std::string& path, const std::string& tmp, const std::string& content) {
  const auto failed = [&](const char* what, int error) {
    std::remove(tmp.c_str());
    throw InputError(fmt::format("{}: cannot {}: {}", path, what, std::strerror(error)));
  };
  std::FILE* out = std::fopen(tmp.c_str(), "wb");
  if (out == nullptr) failed("create the file", errno);
  const bool written = std::fwrite(content.data(), 1, content.size(), out) == content.size() && std::fflush(out) == 0;
  const int write_error = errno;
  if (std::fclose(out) != 0 || !written) failed("write the file", written ? errno : write_error);
}

void rename_into_place(const std::string& tmp, const std::string& path) {
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int error = errno;
    std::remove(tmp.c_str());
    throw InputError(fmt::format("{}: cannot rename it into place: {}", path, std::strerror(error)));
  }
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& content) {
  const std::string tmp = temporary_path_for(path);
  write_temporary(path, tmp, content);
  rename_into_place(tmp, path);
}

void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files) {
  std::vector<std::string> temporaries;
  try {
    for (const auto& [path, content] : files) {
      temporaries.push_back(temporary_path_for(path));
      write_temporary(path, temporaries.back(), content);
    }
  } catch (...) {
    for (const std::string& tmp : temporaries) std::remove(tmp.c_str());
    throw;
  }
  for (std::size_t k = 0; k < files.size(); ++k) rename_into_place(temporaries[k], files[k].first);
}

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return in ? s.str() : std::string();
}

}  // namespace softpack
