#include "render/gait_cues.h"

#include <algorithm>

namespace hexgait {

std::string ParseCues(const std::string& text, CueOptions* cues) {
  CueOptions result;
  if (text == "all") {
    result = {true, true, true, true};
  } else if (text != "none") {
    size_t start = 0;
    while (start <= text.size()) {
      const size_t comma = std::min(text.find(',', start), text.size());
      const std::string name = text.substr(start, comma - start);
      if (name == "footprints") {
        result.footprints = true;
      } else if (name == "trail") {
        result.trail = true;
      } else if (name == "swing") {
        result.swing = true;
      } else if (name == "strip") {
        result.strip = true;
      } else {
        return "unknown cue '" + name + "' (use " + kCueNames + ", all or none)";
      }
      start = comma + 1;
    }
  }
  *cues = result;
  return "";
}

}  // namespace hexgait
