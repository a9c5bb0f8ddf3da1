// The ranges of the numeric parameters of scenes and profiles (SI units), written once: the
// validators (scene/validate.cpp, packing/generator.cpp, measure/settings.cpp) check them and
// their messages quote them; docs/scene-format.md ("Ranges") has the table with the reasons.
//
// Each bound has two reasons. Physical: it lies far beyond any material, grain or run this code
// is for, so that no real input is refused. Numerical: within the bounds every product the
// engine forms stays a finite, normal double (masses rho r^3, moments rho r^5, forces
// E sqrt(R) h^(3/2), energies, the Rayleigh time pi r sqrt(rho / G) / (0.1631 nu + 0.8766),
// within about 1e-24 s to 2e8 s), and every count that sizes a loop or an allocation (time
// steps, relaxation checks, grid levels and cells, insertion trials) stays bounded. A value
// that passes each bound can still fail a rule that relates several (the time steps of a
// duration: duration / dt), which the validators check where both are known.
#pragma once
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <string>

namespace softpack::limits {

/// An interval of allowed values, and how a message writes it ("1 <= E <= 1e13 Pa").
struct Range {
  double lo = 0.0, hi = 0.0;
  bool lo_open = false, hi_open = false;
  const char* name = "";  ///< the symbol in the message
  const char* unit = "";  ///< "" for a number without unit

  /// NaN is in no range.
  constexpr bool contains(double v) const { return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi); }
};

/// "1e+13" -> "1e13", "2.5e-09" -> "2.5e-9".
inline std::string plain_exponent(std::string s) {
  const std::size_t e = s.find('e');
  if (e == std::string::npos) return s;
  std::string exponent = s.substr(e + 1);
  const bool negative = !exponent.empty() && exponent[0] == '-';
  if (!exponent.empty() && (exponent[0] == '+' || exponent[0] == '-')) exponent.erase(0, 1);
  exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
  return s.substr(0, e) + "e" + (negative ? "-" : "") + exponent;
}

/// A number as messages write it, by the shortest text that reads back the same double: with
/// an exponent when that saves three characters or more (1e13, 2e9, 1e5, 2.5e-9), else in
/// decimals (0.3, 1000, 10000, 1048576, 0.001).
inline std::string number_text(double v) {
  const std::string decimal = plain_exponent(fmt::format("{}", v));
  std::string general;
  for (int digits = 1; digits <= 17; ++digits) {
    general = fmt::format("{:.{}g}", v, digits);
    if (std::strtod(general.c_str(), nullptr) == v) break;
  }
  general = plain_exponent(general);
  return general.size() + 3 <= decimal.size() ? general : decimal;
}

/// A computed value, to three digits (1.29e34, 7.74e-05 s -> 7.74e-5).
inline std::string approx_text(double v) { return number_text(std::strtod(fmt::format("{:.3g}", v).c_str(), nullptr)); }

/// "1 <= E <= 1e13 Pa"
inline std::string text(const Range& r) {
  return fmt::format("{} {} {} {} {}{}{}", number_text(r.lo), r.lo_open ? "<" : "<=", r.name, r.hi_open ? "<" : "<=",
                     number_text(r.hi), *r.unit ? " " : "", r.unit);
}

/// "" when `v` is in `r`; else "<v> <unit> is not allowed; allowed: <range>".
inline std::string refusal(double v, const Range& r) {
  if (r.contains(v)) return "";
  return fmt::format("{}{}{} is not allowed; allowed: {}", number_text(v), *r.unit ? " " : "", r.unit, text(r));
}

// --- Lengths -----------------------------------------------------------------------------------
// Radii of spheres and shells, the packing's Rs and smallest radius: from a nanometre to a
// kilometre. With the moduli and densities below they keep every mass, force, energy and time
// step a normal double.
inline constexpr double kMinLength = 1e-9, kMaxLength = 1e3;
inline constexpr Range kRadius{kMinLength, kMaxLength, false, false, "r", "m"};
inline constexpr Range kShellRadius{kMinLength, kMaxLength, false, false, "radius", "m"};
inline constexpr Range kPackingRs{kMinLength, kMaxLength, false, false, "Rs", "m"};
// Each coordinate of a centre or a wall's point: a thousand times the largest radius, so that
// differences of positions (contact normals, torque arms) stay far from overflow. The spread of
// the spheres is bounded further by the contact grid (kGridCells).
inline constexpr Range kCoordinate{-1e6, 1e6, false, false, "coordinate", "m"};

// --- Materials ---------------------------------------------------------------------------------
// Young's modulus: 1 Pa is softer than any solid (gels start near 1e2 Pa); 1e13 Pa is ten times
// diamond's. 1e308 would make the Rayleigh time 1e-156 s and every force infinite.
inline constexpr Range kModulus{1.0, 1e13, false, false, "E", "Pa"};
// The Poisson ratio of an isotropic, stable elastic solid.
inline constexpr Range kPoisson{-1.0, 0.5, true, true, "nu", ""};
// Coulomb friction: measured coefficients stay below ~10; 100 leaves room for a contact that
// must never slide.
inline constexpr Range kFriction{0.0, 100.0, false, false, "mu", ""};
// Density: 1e-3 kg/m^3 is lighter than any solid (aerogels: ~1); 1e9 is 4e4 times osmium, room
// for the density scaling that slows a simulation down (the quick profile uses 2.5e5).
inline constexpr Range kDensity{1e-3, 1e9, false, false, "density", "kg/m^3"};
// A sphere's own mass (a soft-particle's, the mass of its grains): from a 1 nm sphere of the
// lightest density (4e-30 kg) to a 1 km one of the heaviest (4e18 kg).
inline constexpr Range kMass{1e-30, 1e19, false, false, "mass", "kg"};

// --- Motion ------------------------------------------------------------------------------------
// Speeds of spheres and of driven walls and groups: 1e4 m/s is a hypervelocity impact, far above
// any granular flow. For drivers also > 0 (a driver that does not move has no target to reach).
inline constexpr Range kSpeed{0.0, 1e4, false, false, "|v|", "m/s"};
inline constexpr Range kDriveSpeed{0.0, 1e4, true, false, "|velocity|", "m/s"};
// A sphere's spin, as the speed of its surface |w| r, bounded as the speeds.
inline constexpr Range kSurfaceSpeed{0.0, 1e4, false, false, "|w| r", "m/s"};
// Rotation rate of a driven group: 1e6 rad/s is 60 times an ultracentrifuge's.
inline constexpr Range kRate{0.0, 1e6, true, false, "|rate|", "rad/s"};
// Gravity: 1e7 m/s^2 is a million g, an ultracentrifuge's.
inline constexpr Range kGravity{0.0, 1e7, false, false, "|gravity|", "m/s^2"};
// The rotation of a driven group in one time step: beyond it the kinematic spin
// 2 tan(dtheta/2) / dt departs from the rate (by 0.08 % at 0.1 rad), and is infinite at pi.
inline constexpr double kMaxRotationPerStep = 0.1;  // [rad]

// --- Contact law -------------------------------------------------------------------------------
inline constexpr Range kRestitution{0.0, 1.0, true, false, "e", ""};
// The factor on the tangential damping: the engine's model is 1, Tsuji's 1.68; 100 is
// overdamped by orders of magnitude.
inline constexpr Range kTangentialRatio{0.0, 100.0, false, false, "tangential_ratio", ""};

// --- Time steps --------------------------------------------------------------------------------
// The most time steps one duration may ask for (run.duration, a relaxation, a driver's way to its
// target, a sweep point's approach or rotation): 1e12 steps of a single sphere take about a day,
// of a soft-particle years; it is below 2^53, so step counts stay exact as doubles (JSON
// reports), and far below the 2^63 of the step counter. Without it a duration of 1e30 s ran one
// step (the count overflowed) and a modulus of 1e308 asked for 1e155 steps.
inline constexpr double kMaxSteps = 1e12;
inline constexpr Range kSafety{0.0, 1.0, true, false, "safety", ""};

// --- Contact detection -------------------------------------------------------------------------
// The Verlet skin as a fraction of the smallest radius: 100 radii of skin already list far
// neighbours; the finest grid cell grows with it.
inline constexpr Range kSkin{0.0, 100.0, true, false, "skin", ""};
// The cell-size ratio between the levels of a hierarchical grid (contact detection and the
// packing's insertion grid): there are log(r_max / r_min) / log(level_ratio) levels, without
// bound as the ratio nears 1; 1.1 gives at most 290 levels over the lengths above.
inline constexpr Range kLevelRatio{1.1, 1000.0, false, false, "level_ratio", ""};
// The spheres of a scene may span at most this many cells of the finest level of the contact
// grid (2 r_min + skin) along each axis: its cell coordinates have 21 bits
// (neighbor/hierarchical_grid.hpp, kMaxCoordinate).
inline constexpr double kGridCells = 2097151.0;  // 2^21 - 1
// The packing's insertion grid: cell coordinates within +-2^20 cells of 2 r_min
// (packing/insertion_grid.hpp, kOffset), so Rs / (2 r_min) < 2^20.
inline constexpr double kInsertionCells = 1048576.0;  // 2^20

// --- Relaxation and watchdog -------------------------------------------------------------------
// Stops of the paper's protocol (the paper: 6), and checks of the converged one
// (max_time / check_interval): each is a row of the results' relaxation table, so 1e6 rows.
inline constexpr Range kStops{0.0, 1e6, false, false, "stops", ""};
inline constexpr double kMaxChecks = 1e6;
// Steps between two watchdog checks: at least one, at most a run's worth.
inline constexpr Range kCheckInterval{1.0, kMaxSteps, false, false, "check_interval", "steps"};

// --- Packing -----------------------------------------------------------------------------------
inline constexpr Range kRmaxOverRs{0.0, 1.0, true, true, "r_max / Rs", ""};
inline constexpr Range kPolydispersity{1.0, 1e6, true, false, "Pi", ""};
inline constexpr Range kExponent{1.0, 20.0, true, false, "b", ""};
// The list volume over the shell volume: a packing fills at most ~0.74 of the shell, so beyond
// 100 the list is only spheres to discard.
inline constexpr Range kBeta{0.0, 100.0, true, false, "beta", ""};
// Random positions tried per sphere: the solid fraction grows only slowly beyond 1000 (0.69 at
// 1000, 0.71 at 3000: docs/packing.md); 1e6 bounds the insertion to 1e6 tries of each of at
// most 5e7 spheres.
inline constexpr Range kTrials{1.0, 1e6, false, false, "I", ""};

}  // namespace softpack::limits
