// SHA-256 (OpenSSL's libcrypto), as 64 lowercase hex digits: the digest an imported packing
// records of its source file, and that its stage stamp depends on; and the identity of a packing
// by its content (formats/packing_file.hpp, packing_sha256), which the averages check.
#pragma once
#include <string>
#include <string_view>

namespace softpack {

/// InputError naming the file when it cannot be read.
std::string sha256_of_file(const std::string& path);

/// Of bytes in memory.
std::string sha256_of_bytes(std::string_view bytes);

}  // namespace softpack
