// SHA-256 of a file's bytes (OpenSSL's libcrypto), as 64 lowercase hex digits: the digest an
// imported packing records of its source file, and that its stage stamp depends on.
#pragma once
#include <string>

namespace softpack {

/// InputError naming the file when it cannot be read.
std::string sha256_of_file(const std::string& path);

}  // namespace softpack
