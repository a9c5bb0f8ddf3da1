#include "core/text_input.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/error.hpp"

namespace softpack {

std::string read_text_input(const std::string& path, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec) {
    if (ec == std::errc::too_many_symbolic_link_levels)
      throw InputError(fmt::format("{}: cannot open the file (a symlink loop); expected {}", path, what));
    throw InputError(fmt::format("{}: cannot open the file ({})", path, ec.message()));
  }
  if (fs::is_directory(st)) throw InputError(fmt::format("{}: is a directory, expected {}", path, what));
  if (!fs::is_regular_file(st))
    throw InputError(fmt::format("{}: is not a regular file (a device, a pipe or a socket); expected {}", path, what));
  const auto size = fs::file_size(path, ec);
  if (!ec && size > kMaxTextInput)
    throw InputError(fmt::format("{}: {} bytes; allowed: at most {} bytes for {}", path, size, kMaxTextInput, what));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot open the file ({})", path, std::strerror(errno)));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(fmt::format("{}: cannot read the file ({})", path, std::strerror(errno)));
  return text.str();
}

}  // namespace softpack
