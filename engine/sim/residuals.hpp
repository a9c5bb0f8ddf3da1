// Residuals of a state: how far it is from rest (the relaxation protocols, relax/) and from the
// physical regime (the watchdog, sim/watchdog.hpp). Computed from the closed contacts as the
// normal law sees them (forces/contact_walk.hpp) and from the free spheres' motion.
#pragma once
#include <cstddef>

#include "forces/force_field.hpp"
#include "neighbor/contact_list.hpp"
#include "state/world.hpp"

namespace softpack {

struct Measurement {
  double kinetic_energy = 0.0;        ///< free spheres (and free shells), translation + rotation [J]
  double elastic_energy = 0.0;        ///< normal law + tangential springs [J]
  double spring_energy = 0.0;         ///< of which the tangential springs' ½ kt ξ² [J]
  double max_unbalanced_force = 0.0;  ///< largest |net force| on a free sphere [N]
  double mean_contact_force = 0.0;    ///< mean normal force over closed contacts [N]
  std::size_t contacts = 0;           ///< closed contacts (sphere-sphere and sphere-wall)
  /// Deepest contact relative to its smaller radius (a sphere's own radius against a wall; a
  /// soft-particle's contact relative to its law's R, i.e. its Δn):
  /// spheres i and j, or sphere i and plane `plane` or shell `shell` (j = -1). i = -1: none.
  struct Deepest {
    double fraction = 0.0, overlap = 0.0;  ///< h / radius [-], h [m]
    int i = -1, j = -1, plane = -1, shell = -1;
  } deepest;
  int hottest = -1;             ///< free sphere with the largest kinetic energy (-1: none moves)
  double hottest_energy = 0.0;  ///< its kinetic energy [J]
  /// max unbalanced force / mean contact force (0 for a state with no force at all).
  double force_ratio() const;
  /// kinetic energy / elastic energy (0 when both vanish).
  double energy_ratio() const;
};

Measurement residuals(const World& world, const ContactLists& lists, const ForceField& forces);

/// The value a fraction `q` (0 < q <= 1) of the closed contacts do not exceed of h / r, with r the
/// smaller radius of the contact (a sphere's own against a wall), as Measurement::Deepest; 0
/// with no contact. The Hertz law holds for h / r << 1: beside the deepest contact, q = 0.99
/// says whether a few pinned grains or the network leave that range.
double overlap_quantile(const World& world, const ContactLists& lists, const ForceField& forces, double q);

}  // namespace softpack
