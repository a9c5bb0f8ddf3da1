// Typed fields of the softpack HDF5 files, shared by the format modules (formats/*_file.cpp).
// Each module lists its fields once, as (dataset, member) pairs in the file's order, and its
// writer and its reader both walk that list, with put() and get() for every member type.
//
// get() checks what every softpack file guarantees: numbers are finite, counts and seeds are
// >= 0, flags are 0 or 1, a Vec3 is 3 values and a list of them has shape (N, 3). Lists of
// numbers are read as stored (their columns are checked by the module: check_finite,
// same_length). InputError names the file and the dataset.
#pragma once
#include <concepts>
#include <cstdint>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "io/hdf5_file.hpp"

namespace softpack::formats {

void put(h5::File& f, const std::string& name, double v);
void put(h5::File& f, const std::string& name, std::int64_t v);
template <std::integral T>
void put(h5::File& f, const std::string& name, T v) {  // counts, seeds, flags (0 or 1)
  put(f, name, static_cast<std::int64_t>(v));
}
void put(h5::File& f, const std::string& name, const std::string& v);
void put(h5::File& f, const std::string& name, const Vec3& v);
void put(h5::File& f, const std::string& name, const std::vector<double>& v);
void put(h5::File& f, const std::string& name, const std::vector<std::int64_t>& v);
void put(h5::File& f, const std::string& name, const std::vector<Vec3>& v);  ///< shape (N, 3)

void get(const h5::File& f, const std::string& name, double& v);
void get(const h5::File& f, const std::string& name, bool& v);
std::int64_t get_count(const h5::File& f, const std::string& name);  ///< an integer >= 0
template <std::integral T>
void get(const h5::File& f, const std::string& name, T& v) {
  v = static_cast<T>(get_count(f, name));
}
void get(const h5::File& f, const std::string& name, std::string& v);
void get(const h5::File& f, const std::string& name, Vec3& v);
void get(const h5::File& f, const std::string& name, std::vector<double>& v);
void get(const h5::File& f, const std::string& name, std::vector<std::int64_t>& v);
void get(const h5::File& f, const std::string& name, std::vector<Vec3>& v);

/// Where every result file records its configuration stamp (profile/profile.hpp; since issue 28,
/// absent in older files).
inline constexpr const char* kProvenanceStamp = "provenance/stamp";

/// f(name, member) for a module's field lists: put() or get() each member.
inline auto writer(h5::File& f) {
  return [&f](const std::string& name, const auto& member) { put(f, name, member); };
}
inline auto reader(const h5::File& f) {
  return [&f](const std::string& name, auto& member) { get(f, name, member); };
}

/// InputError unless every value of the dataset `name` is finite.
void check_finite(const h5::File& f, const std::string& name, const std::vector<double>& v);
/// InputError unless the dataset `name` has as many entries (n) as the dataset `ref` (n_ref).
void same_length(const h5::File& f, const std::string& name, std::size_t n, const std::string& ref, std::size_t n_ref);

}  // namespace softpack::formats
