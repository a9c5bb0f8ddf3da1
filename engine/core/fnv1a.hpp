// 64-bit FNV-1a (Fowler-Noll-Vo): a small, fast, non-cryptographic hash of bytes, for the
// configuration stamps and the digests of result bits. Not for integrity (that is SHA-256).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace softpack {

struct Fnv1a {
  std::uint64_t value = 1469598103934665603ull;  // the offset basis

  void add(const void* data, std::size_t bytes) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < bytes; ++k) value = (value ^ b[k]) * 1099511628211ull;  // the FNV prime
  }
  void add(std::string_view text) { add(text.data(), text.size()); }
};

}  // namespace softpack
