#include "core/random.hpp"

#include <fmt/format.h>

#include "core/integer_text.hpp"

namespace softpack {
namespace {

std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

}  // namespace

namespace {

// The text as it may appear in a one-line message: control characters shown as '?'.
std::string printable_text(std::string_view text) {
  std::string out(text);
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) c = '?';
  return out;
}

}  // namespace

std::optional<std::uint64_t> parse_seed(std::string_view text, std::string& error) {
  const IntegerText v = parse_integer(text);
  if (v.status == IntegerText::Status::ok && v.value >= 0) return static_cast<std::uint64_t>(v.value);
  error = fmt::format("'{}' is not allowed; allowed: a seed, an integer 0 <= seed <= {} (2^63 - 1) in decimal digits "
                      "(no sign, point, exponent or leading zero)",
                      printable_text(text), kMaxSeed);
  return std::nullopt;
}

Random::Random(std::uint64_t seed) {
  for (auto& s : s_) s = splitmix64(seed);
}

std::uint64_t Random::bits() {
  const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
  const std::uint64_t t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = rotl(s_[3], 45);
  return result;
}

Vec3 Random::in_ball(double R) {
  for (;;) {
    const Vec3 p = in_box(R);
    if (p.squaredNorm() < R * R) return p;
  }
}

}  // namespace softpack
