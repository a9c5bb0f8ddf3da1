// Materials and the contact constants that two materials share (paper Eq. 4 and Eq. 6).
#pragma once
#include <string>

namespace softpack {

struct Material {
  std::string name;
  double E = 0.0;        ///< Young's modulus [Pa]
  double nu = 0.0;       ///< Poisson ratio [-]
  double mu = 0.0;       ///< Coulomb friction coefficient [-]
  double density = 0.0;  ///< [kg/m^3]
};

/// Paper Eq. 4: D = 3/4 ((1 - nu^2)/E + (1 - nu'^2)/E')  [1/Pa].
double hertz_D(const Material& a, const Material& b);

/// Paper Eq. 6 generalised to two materials through Mindlin's effective shear modulus:
/// Dt = 8 G* with 1/G* = (2 - nu)/G + (2 - nu')/G', G = E / (2 (1 + nu)).
/// For identical materials this is exactly Eq. 6, Dt = 2E / ((2 - nu)(1 + nu))  [Pa].
double tsuji_Dt(const Material& a, const Material& b);

/// Friction coefficient of a contact between two materials: the geometric mean (as LAMMPS
/// mixes mu); for identical materials it is the paper's mu.
double contact_mu(const Material& a, const Material& b);

/// Shear modulus G = E / (2 (1 + nu)).
double shear_modulus(const Material& m);

}  // namespace softpack
