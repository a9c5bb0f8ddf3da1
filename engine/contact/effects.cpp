#include "contact/effects.hpp"

namespace softpack {

std::string describe(const Effects& fx) {
  std::string out = "normal law";
  if (fx.friction) out += ", friction";
  if (fx.damping) out += ", damping";
  if (fx.rotation) out += ", rotation";
  if (fx.synchronized) out += ", synchronized spring";
  return out;
}

}  // namespace softpack
