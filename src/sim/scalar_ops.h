// Physics<Ops> (sim/physics_terms.h) on one double: the scalar path's operations. In an
// anonymous namespace, as every Ops is, so each translation unit's instantiations stay its own.
#pragma once

#include <cmath>

#include "sim/physics_terms.h"

namespace hexgait {
namespace {

struct ScalarOps {
  using T = double;
  using V = double;
  using M = bool;
  static V Splat(T value) { return value; }
  static V Sqrt(V v) { return std::sqrt(v); }
  static M GreaterEqual(V a, V b) { return a >= b; }
  static M LessEqual(V a, V b) { return a <= b; }
  static M NeitherOf(M a, M b) { return !a && !b; }
  static bool All(M m) { return m; }
  static V Select(M m, V a, V b) { return m ? a : b; }
};

using ScalarPhysics = Physics<ScalarOps>;

}  // namespace
}  // namespace hexgait
