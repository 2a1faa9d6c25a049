// Text for HTML: the report page and the replay page write titles and captions through this.
#pragma once

#include <string>

namespace hexgait {

// `text` with &, <, > and " escaped, for element content and double-quoted attributes.
inline std::string HtmlEscape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace hexgait
