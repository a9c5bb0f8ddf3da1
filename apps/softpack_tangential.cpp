// softpack-tangential: the tangential sweep of one contact scene and one seed (paper §4); see
// measure/sweeps.hpp for what it does and docs/measurement.md for the choices.
#include "apps/stage_cli.hpp"

namespace softpack::apps::tangential_app {

int main(int argc, char** argv) { return softpack::stage_main(argc, argv, "tangential"); }

}  // namespace softpack::apps::tangential_app
