// A nested soft-particle's content resolved in a scene (docs/nested.md): each site's level
// packing in a free shell whose parent is the enclosing body, and so on down to the last level.
// Read by the measurement scenes (measure/contact_scenes.cpp) and by the coarse-grain medium
// (coarse/medium.cpp), so that a site's content is one thing wherever it is resolved.
#pragma once
#include <vector>

#include "packing/nested.hpp"
#include "scene/scene_def.hpp"

namespace softpack {

/// How a content's spheres and shells enter a scene.
struct ContentPlacement {
  int grain_material = 0, wall_material = 1;  ///< the scene's materials of grains and shells
  double density = 0.0;                       ///< of the grains [kg/m^3]
  ShellContactRadius contact_radius = ShellContactRadius::concave;
  double shell_mass_fraction = 0.0;  ///< a free shell's mass / the mass of every grain inside it
};

/// The mass of the free shells of `c` resolved: its own shell and every site's inside it, each
/// shell_mass_fraction times the mass of every grain inside it [kg].
double content_shells_mass(const SiteContent& c, double density, double shell_mass_fraction);

/// The contents of `sites` (centres about the enclosing body's centre, radius `site_radius`)
/// resolved about `centre`, every length times `scale`: each in a free shell whose parent is
/// `body` (weighing `place.shell_mass_fraction` times every grain inside it, scaled as
/// length^3), its grains a body of their own numbered from `next_body` on, and so on down.
void add_contents(SceneDef& scene, const std::vector<SiteContent>& contents, const std::vector<Vec3>& sites, double site_radius,
                  int body, const Vec3& centre, double scale, const ContentPlacement& place, int& next_body);

}  // namespace softpack
