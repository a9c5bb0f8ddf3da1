#include "formats/h5_fields.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

#include "core/error.hpp"

namespace softpack::formats {

void put(h5::File& f, const std::string& name, double v) { f.write_scalar(name, v); }
void put(h5::File& f, const std::string& name, std::int64_t v) { f.write_scalar(name, v); }
void put(h5::File& f, const std::string& name, const std::string& v) { f.write_string(name, v); }
void put(h5::File& f, const std::string& name, const Vec3& v) { f.write(name, std::vector<double>{v.x(), v.y(), v.z()}); }
void put(h5::File& f, const std::string& name, const std::vector<double>& v) { f.write(name, v); }
void put(h5::File& f, const std::string& name, const std::vector<std::int64_t>& v) { f.write(name, v); }
void put(h5::File& f, const std::string& name, const std::vector<Vec3>& v) {
  std::vector<double> flat;
  flat.reserve(3 * v.size());
  for (const Vec3& x : v) flat.insert(flat.end(), {x.x(), x.y(), x.z()});
  f.write(name, flat, {v.size(), 3});
}

void get(const h5::File& f, const std::string& name, double& v) {
  v = f.read_scalar_double(name);
  if (!std::isfinite(v)) throw InputError(fmt::format("{}: /{} = {} is not allowed; allowed: a finite number", f.path(), name, v));
}

void get(const h5::File& f, const std::string& name, bool& v) {
  const std::int64_t i = f.read_scalar_int64(name);
  if (i != 0 && i != 1) throw InputError(fmt::format("{}: /{}: {} is not allowed; allowed: 0 or 1", f.path(), name, i));
  v = i == 1;
}

std::int64_t get_count(const h5::File& f, const std::string& name) {
  const std::int64_t v = f.read_scalar_int64(name);
  if (v < 0) throw InputError(fmt::format("{}: /{}: {} is not allowed; allowed: >= 0", f.path(), name, v));
  return v;
}

void get(const h5::File& f, const std::string& name, std::string& v) { v = f.read_string(name); }

void get(const h5::File& f, const std::string& name, Vec3& v) {
  const auto x = f.read_doubles(name);
  if (x.size() != 3) throw InputError(fmt::format("{}: /{}: expected 3 values, found {}", f.path(), name, x.size()));
  check_finite(f, name, x);
  v = Vec3(x[0], x[1], x[2]);
}

void get(const h5::File& f, const std::string& name, std::vector<double>& v) { v = f.read_doubles(name); }
void get(const h5::File& f, const std::string& name, std::vector<std::int64_t>& v) { v = f.read_int64s(name); }

void get(const h5::File& f, const std::string& name, std::vector<Vec3>& v) {
  std::vector<std::size_t> dims;
  const auto x = f.read_doubles(name, &dims);
  if (dims.size() != 2 || dims[1] != 3)
    throw InputError(fmt::format("{}: /{}: expected shape (N, 3), found ({})", f.path(), name, fmt::join(dims, ", ")));
  check_finite(f, name, x);
  v.clear();
  v.reserve(dims[0]);
  for (std::size_t k = 0; k < dims[0]; ++k) v.emplace_back(x[3 * k], x[3 * k + 1], x[3 * k + 2]);
}

void check_finite(const h5::File& f, const std::string& name, const std::vector<double>& v) {
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]))
      throw InputError(fmt::format("{}: /{}[{}] = {} is not allowed; allowed: finite numbers", f.path(), name, i, v[i]));
}

void same_length(const h5::File& f, const std::string& name, std::size_t n, const std::string& ref, std::size_t n_ref) {
  if (n != n_ref)
    throw InputError(fmt::format("{}: /{} has {} values but /{} has {}; allowed: the same number", f.path(), name, n, ref, n_ref));
}

}  // namespace softpack::formats
