// A contact model (contact/contact_model.hpp) as a scene runs it: its parameters from the scene,
// the constants of new contacts, its force loops compiled for the scene's effects
// (forces/compile_loops.hpp), and its scalar formulas for the walk over closed contacts
// (forces/contact_walk.hpp: residuals, watchdog, force between bodies). The loops of every model
// are the same loops (forces/contact_loop.hpp), over that model's list family
// (neighbor/contact_list.hpp ContactFamily).
//
// The registry: the engine's own models are listed once, in forces/contact_models.cpp (the
// paper's Hertz-Tsuji model, `effects.normal: hertz`; the soft-particle model, for the contacts
// of the spheres a scene marks `soft`); a program may add its own with add_contact_model()
// (tests/physics/test_normal_law_registry.cpp adds two). docs/architecture.md, "Adding a normal
// law", says how.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "contact/contact_model.hpp"
#include "contact/effects.hpp"
#include "neighbor/contact_list.hpp"
#include "state/world.hpp"

namespace softpack {

/// How far a model's contacts went beyond the overlaps its law was measured on (a model that
/// declares such a range: the soft-particle model, Δn = h / R).
struct RangeStats {
  long beyond_range = 0;  ///< contact evaluations with Δn above the law's measured range
  double max_dn = 0.0;    ///< the largest Δn met
  int i = -1, j = -1;     ///< its spheres (j = -1: sphere i against plane `plane`)
  int plane = -1;
};

class SceneModel {
 public:
  virtual ~SceneModel() = default;
  virtual const char* name() const = 0;
  /// The number of per-contact constants (the arrays of ConstantArrays).
  virtual std::size_t constants() const = 0;
  /// The model declares a body state (contact/contact_model.hpp BodyStateModel).
  virtual bool body_state() const = 0;
  /// Sets the constants of contact k.
  virtual void set(ConstantArrays& a, std::size_t k, const ContactPartners& b) const = 0;

  /// The forces of the touching contacts of `lists`, added to the spheres' F (and T) and the
  /// walls' loads; springs advanced by `spring_dt`, those of open contacts cleared. A model with
  /// a measured range counts (or, when the scene says so, stops at: NumericalError) the
  /// contacts beyond it.
  virtual void run(World& world, ContactFamily& lists, double spring_dt, std::vector<std::int32_t>& scratch) = 0;
  /// The active set's frozen sums (sim/active_set.hpp): adds `sign` times the force and torque of
  /// each touching pair k with mask[k] != 0 to F and T (arrays of the spheres' size), springs not
  /// advanced (dt = 0) and not written back.
  virtual void add_pair_forces(World& world, PairList& pairs, const std::uint8_t* mask, double sign, Vec3* F, Vec3* T,
                               std::vector<std::int32_t>& scratch) const = 0;

  // One closed contact k of array `a`, at overlap g.h, its bodies' states g.body1, g.body2 and
  // (a law with a stress term) its normal g.n and its bodies' tensors g.stress1, g.stress2.
  virtual double Fn(const ConstantArrays& a, std::size_t k, const ContactGeometry<double>& g) const = 0;  ///< [N]
  /// [J]; a law's stress term is not the derivative of a potential and is left out.
  virtual double normal_energy(const ConstantArrays& a, std::size_t k, const ContactGeometry<double>& g) const = 0;
  /// Tangential stiffness [N/m] (a model with a body state: at its bodies' states).
  virtual double kt(const ConstantArrays& a, std::size_t k, const ContactGeometry<double>& g) const = 0;
  /// The length an overlap is measured against: `r_min` (the smaller sphere's radius) unless
  /// the model says otherwise (the soft-particle model: its R, so that h / R is Δn).
  virtual double overlap_scale(const ConstantArrays& a, std::size_t k, double r_min) const = 0;
  /// What run() counted (all zero for a model without a measured range).
  virtual const RangeStats& range() const = 0;
};

struct ContactModelType {
  std::string name;         ///< the value of effects.normal
  /// A model a scene may name in effects.normal (false: the soft-particle model, which runs the
  /// contacts of the spheres a scene marks soft).
  bool of_scene = true;
  std::unique_ptr<SceneModel> (*make)(const ContactSetting& setting, Effects fx) = nullptr;
};

/// The registered model of that name (`of_scene`: one a scene may name). InputError
/// "effects.normal: ..." with the names allowed (and the closest one) otherwise.
const ContactModelType& contact_model(const std::string& name, bool of_scene = true);
/// Registers a model; std::invalid_argument when the name is taken.
void add_contact_model(ContactModelType model);

}  // namespace softpack
