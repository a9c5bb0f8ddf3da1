// The two measurement scenes of paper §4, built from packing files. Coordinates: the first
// soft-particle's shell is centred at the origin and fixed; the second body touches it on the
// +x side (hn = 0) and is moved along -x to impose the normal deformation hn.
//
//   soft-solid: the second body is a plane wall (a solid sphere of infinite radius) at x = Rs,
//               normal -x, named "wall";
//   soft-soft:  the second body is a soft-particle of equal size from another packing, centred
//               at (2 Rs, 0, 0): its shell "shell-2" (body 1) and its spheres. With
//               normal.second_radius_ratio k != 1 that packing is scaled by k (radius k Rs, the
//               self-similar soft-particle of that size), centred at ((1 + k) Rs, 0, 0).
//
// The force on the second body is what holds it in place: the load on the wall, or on the
// second shell (in balance, the spheres of the second body carry to their shell the force the
// first body exerts on them). Its x component is the normal force Fn, y and z the tangential
// ones; the tangential stage turns the first soft-particle about +z, so +y is the direction of
// the tangential deformation; the sliding stage moves the second body along +y.
#pragma once
#include <string>

#include "formats/packing_file.hpp"
#include "measure/settings.hpp"
#include "scene/scene_def.hpp"

namespace softpack {

struct ContactSetup {
  ContactScene kind = ContactScene::soft_solid;
  SceneDef scene;
  double Rs = 0.0;
  std::string second_wall;  ///< the wall or shell whose load is the force on the second body
  std::string first_shell;  ///< "shell-1" (absent in the Hertz check)
  int first_body = 0;
  int second_body = -1;     ///< body of the second soft-particle's spheres (soft-soft), else -1
};

/// Soft-particle against a plane wall.
ContactSetup soft_solid_setup(const PackingFile& first, const SimulationSettings& s);
/// Two soft-particles: of equal size, or the second's packing scaled by `second_radius_ratio`.
ContactSetup soft_soft_setup(const PackingFile& first, const PackingFile& second, const SimulationSettings& s,
                             double second_radius_ratio = 1.0);
/// The soft-particle replaced by one solid sphere of radius Rs held at the origin, against the
/// wall: the chain must measure Hertz's law (Eq. 3) for it.
ContactSetup hertz_check_setup(double Rs, const SimulationSettings& s);

}  // namespace softpack
