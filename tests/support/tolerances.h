// Test tolerances in one place. HEXGAIT_TOL_SCALE (environment) multiplies every tolerance,
// for example on a platform with a different libm.
#pragma once

#include <cstdlib>

namespace hexgait::test {

inline double TolScale() {
  const char* s = std::getenv("HEXGAIT_TOL_SCALE");
  return s ? std::atof(s) : 1.0;
}

// Finite-difference checks with central differences and step 1e-6: truncation ~1e-12 relative,
// round-off ~1e-10 relative.
inline double FiniteDifferenceTol() {
  return 1e-6 * TolScale();
}
// Quantities that must be conserved exactly up to rounding over a few thousand steps.
inline double ConservationTol() {
  return 1e-9 * TolScale();
}

}  // namespace hexgait::test
