// softpack-sliding: the sliding measurement of one contact scene and one seed (issue 16, the
// soft-particle's friction coefficient); see measure/sweeps.hpp for what it does and
// docs/radius.md for the choices.
#include "apps/stage_cli.hpp"

namespace softpack::apps::sliding_app {

int main(int argc, char** argv) { return softpack::stage_main(argc, argv, "sliding"); }

}  // namespace softpack::apps::sliding_app
