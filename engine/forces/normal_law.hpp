// A normal contact law as the engine sees it at run time: its scalar formulas (for the
// constants of new contacts, the residuals, the watchdog and force_between) and its force loops,
// compiled for every combination of effects (forces/compile_loops.hpp). The scene chooses one
// by name (`effects.normal: hertz`).
//
// The registry: the engine's own laws are listed once, in forces/normal_laws.cpp; a program may
// add its own with add_normal_law() (tests/physics/test_normal_law_registry.cpp adds a linear
// spring). docs/architecture.md, "Adding a normal law", says how.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "contact/effects.hpp"
#include "neighbor/contact_list.hpp"
#include "state/world.hpp"

namespace softpack {

/// The contact forces of every touching contact of a world, for one law and one set of effects:
/// added to the spheres' F (and T) and to the wall loads; springs advanced by `spring_dt`.
class ForceLoops {
 public:
  virtual ~ForceLoops() = default;
  virtual void run(World& world, ContactLists& lists, double spring_dt, std::vector<std::int32_t>& scratch) const = 0;
  /// The active set's frozen sums (sim/active_set.hpp): adds `sign` times the force and torque of
  /// each touching pair k with mask[k] != 0 to F and T (arrays of the spheres' size), springs not
  /// advanced (dt = 0) and not written back.
  virtual void add_pair_forces(World& world, PairList& pairs, const std::uint8_t* mask, double sign, Vec3* F, Vec3* T,
                               std::vector<std::int32_t>& scratch) const = 0;
};

struct NormalLaw {
  std::string name;  ///< the value of effects.normal
  double (*stiffness)(double R12, double D) = nullptr;  ///< the per-contact constant kn
  /// Fn [N] and the elastic energy [J] of a contact whose bodies have states s1, s2 (read
  /// only by a law with a body state: contact/hertz_normal.hpp).
  double (*force)(double kn, double h, double s1, double s2) = nullptr;
  double (*energy)(double kn, double h, double s1, double s2) = nullptr;
  bool body_state = false;  ///< the law declares a body state (contact/contact_law.hpp BodyStateLaw)
  double (*damping_coefficient)(double restitution) = nullptr;
  std::unique_ptr<ForceLoops> (*loops)(Effects fx) = nullptr;
};

/// The registered law of that name. InputError "effects.normal: ..." with the registered names
/// (and the closest one) otherwise.
const NormalLaw& normal_law(const std::string& name);
/// Registers a law; std::invalid_argument when the name is taken.
void add_normal_law(NormalLaw law);

}  // namespace softpack
