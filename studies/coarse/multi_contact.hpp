// The multi-contact probe (docs/coarse-grain.md, "Why"; issue 33's many-body probe): one
// soft-particle resolved — a packing of the medium's generator in its shell, the shell held —
// pressed by plane walls at once in an arrangement: wall k, its normal towards the centre along
// -u_k, moved in by Δn_k Rs = w_k Δn Rs (u_k a unit direction, w_k in (0, 1] its share of the
// arrangement's Δn), with the laws' own approach speed and relaxation (the profile's
// normal.speed and relaxation). Each wall's force along u_k after the relaxation says whether a
// soft-particle answers each contact as if it were alone (the pairwise laws of the law file:
// the arrangement `one` is the soft-solid measurement itself), or stiffer, its packing being
// compressed by all of them.
//
// Arrangements (builtin_arrangement; the first wall is always +z, with w = 1):
//   one            +z
//   opposite       +z, -z
//   orthogonal     +z, +x
//   triangle       three in the x-z plane at 120 degrees
//   tetrahedral    the four vertices of a regular tetrahedron
//   square         +z, +x, -z, -x (four in a plane)
//   pyramid        the cube's faces but -y (five)
//   cube           the six faces of a cube: +z, -z, +x, -x, +y, -y
//   opposite-half, orthogonal-half   as opposite, orthogonal with the second wall at w = 1/2
//   random-N       N directions (2 <= N <= 12) drawn uniformly on the sphere from the packing's
//                  seed, each at least 60 degrees from the others (40 for N > 6), the first
//                  turned onto +z
//
// NAME:BODY+walls-D presses with BODY at the first contact only, the others being walls moved in
// to Δn = D first and then held; the first contact is moved through the run's Δn from contact.
//
// NAME:BODY presses with another body at every contact of arrangement NAME (PressingBody): a
// held solid sphere (grain-X, radius X Rs, touching the shell from outside at the start) or a
// resolved soft-particle of the same radius (soft: its packing of seed 1000 S + k for contact k,
// its shell moved in and then held, the measurement's soft-soft scene). Body k's force is the
// wall's load, the force of the centre's grains on the grain, or the load on the soft-particle's
// shell, along u_k. Held grains of neighbouring contacts may overlap each other (large grains,
// deep Δn), as the walls of the cube intersect: the soft-particle's boundary is what is measured;
// their mutual forces do not enter body k's force (its contacts with the soft-particle's grains).
//
// The confined shear (measure_confined_shear): from each state at Δn of a walls' arrangement,
// the first wall (+z) slides along +x to each ht in turn, each relaxed; then the next Δn starts
// again from the unsheared state.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "coarse/settings.hpp"
#include "core/types.hpp"

namespace softpack {

struct ProbeWall {
  Vec3 u = Vec3::UnitZ();  ///< unit direction from the centre to the wall
  double w = 1.0;          ///< Δn of this wall / Δn of the arrangement, in (0, 1]
};

/// What presses the soft-particle at each contact of an arrangement.
struct PressingBody {
  enum class Kind { wall, grain, soft } kind = Kind::wall;
  double radius_ratio = 1.0;  ///< grain: its radius over Rs
  /// > 0 (BODY+walls-D): only the first contact is this body, moved through the run's Δn; the
  /// others are walls, first moved in to Δn = walls_at together, then held (the body pressing a
  /// soft-particle that other bodies already confine).
  double walls_at = 0.0;
  std::string name() const;   ///< wall, grain-X, soft, each +walls-D with walls_at
  /// The body at contact k.
  Kind kind_at(std::size_t k) const { return k == 0 || walls_at == 0.0 ? kind : Kind::wall; }
};
/// "wall", "soft" or "grain-X" (0.05 <= X <= 20), each also followed by "+walls-D" (0 < D <= 0.5;
/// wall+walls-D: the first wall moved, the others held at D); InputError naming the allowed ones otherwise.
PressingBody parse_pressing_body(const std::string& name);

struct ProbeArrangement {
  std::string name;  ///< as given: NAME or NAME:BODY
  std::vector<ProbeWall> walls;
  PressingBody body;
};

/// The arrangement named `name` (above); `seed` draws random-N's directions. InputError naming
/// the allowed names otherwise.
ProbeArrangement builtin_arrangement(const std::string& name, std::uint64_t seed);

struct MultiContactPoint {
  std::string arrangement;
  double delta_n = 0.0;     ///< the arrangement's Δn (wall k's is w_k Δn)
  std::vector<double> Fn;   ///< each wall's force along its u, after the relaxation [N]
  /// Empty, or why the point has no forces: the run stopped (the watchdog's NumericalError, e.g. a
  /// grain pressed beyond the overlap limit), and the arrangement's larger Δn were not tried.
  std::string failed;
};

/// For each arrangement and each Δn of `delta_n` (increasing, from contact), the bodies' forces; a
/// point whose run stops is returned with `failed` set and ends its arrangement.
std::vector<MultiContactPoint> measure_multi_contact(const CoarseGrainSettings& s, std::uint64_t packing_seed,
                                                     const std::vector<ProbeArrangement>& arrangements,
                                                     const std::vector<double>& delta_n,
                                                     const std::function<void(const MultiContactPoint&)>& progress = {});

struct ShearPoint {
  std::string arrangement;
  double delta_n = 0.0;
  double ht = 0.0;         ///< the first wall's slide along +x over Rs (0: the unsheared state)
  double Fn = 0.0, Ft = 0.0;  ///< the first wall's force along +z and -x [N]
  std::string failed;      ///< as MultiContactPoint's: the rest of this Δn's slides not tried
};

/// The confined shear (above) of walls' arrangements: for each Δn, the point ht = 0, then each of
/// `ht_over_Rs` (increasing, > 0), at the probe's approach speed.
std::vector<ShearPoint> measure_confined_shear(const CoarseGrainSettings& s, std::uint64_t packing_seed,
                                               const std::vector<ProbeArrangement>& arrangements, const std::vector<double>& delta_n,
                                               const std::vector<double>& ht_over_Rs,
                                               const std::function<void(const ShearPoint&)>& progress = {});

/// OUT: the probe's points, a block per arrangement (its walls' directions and weights, then a row
/// per Δn: walls delta_n Fn_1 ... Fn_walls), with a header naming `source`, the packing seed, the
/// code version and the CPU time; `stamp` as below.
void write_multi_contact(const std::string& out, const std::string& source, std::uint64_t seed, const std::vector<ProbeArrangement>& arrangements,
                         const std::vector<MultiContactPoint>& points, double cpu_seconds, const std::string& stamp = "");

/// OUT: the confined shear's points, a row each (arrangement delta_n ht/Rs Fn Ft), with a header
/// naming `source`, the packing seed, the code version and the CPU time.
/// `stamp`: the first line, "# stamp HASH" of the run's group (a plan's runs_stamps), or empty.
void write_confined_shear(const std::string& out, const std::string& source, std::uint64_t seed, const std::vector<ShearPoint>& sheared, double cpu_seconds,
                          const std::string& stamp = "");

}  // namespace softpack
