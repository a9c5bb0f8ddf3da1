#include "measure/content_scene.hpp"

#include <fmt/format.h>

namespace softpack {

double content_shells_mass(const SiteContent& c, double density, double fraction) {
  double m = fraction * density * c.solid_volume();
  for (const SiteContent& sub : c.sites) m += content_shells_mass(sub, density, fraction);
  return m;
}

void add_contents(SceneDef& scene, const std::vector<SiteContent>& contents, const std::vector<Vec3>& sites, double site_radius,
                  int body, const Vec3& centre, double scale, const ContentPlacement& place, int& next_body) {
  for (std::size_t k = 0; k < contents.size(); ++k) {
    const SiteContent& c = contents[k];
    const int inner = next_body++;
    const Vec3 at = centre + scale * sites[k];
    for (std::size_t i = 0; i < c.level.grains.radii.size(); ++i) {
      ParticleDef d;
      d.x = at + scale * c.level.grains.centres[i];
      d.r = scale * c.level.grains.radii[i];
      d.body = inner;
      d.material = place.grain_material;
      scene.particles.push_back(d);
    }
    // The grains' mass scaled as every length^3, as the scaled spheres' own masses are.
    const double grains = scale * scale * scale * place.density * c.solid_volume();
    ShellDef shell{fmt::format("site-{}", inner), inner, at, scale * site_radius, place.wall_material, place.contact_radius,
                   place.shell_mass_fraction * grains};
    shell.parent = body;
    scene.shells.push_back(shell);
    add_contents(scene, c.sites, c.level.sites, c.level.site_radius, inner, at, scale, place, next_body);
  }
}

}  // namespace softpack
