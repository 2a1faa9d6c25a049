// Numbers as the report files write them: exact for data (CSV cells a script reads back) and
// fixed for prose and tables.
#pragma once

#include <cstdio>
#include <string>

namespace hexgait {

// %.17g: the double round-trips.
inline std::string Exact(double v) {
  char text[48];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

inline std::string Fixed(double v, int digits) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

}  // namespace hexgait
