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

// Serialised JSON made safe inside a <script> element: every <, > and & (which JSON allows only
// inside strings) becomes its \u escape, so no text a user named (a title, a creature, a path)
// can end the element ("</script>") or switch the HTML parser into its escaped state
// ("<!--<script>", which blanks the page); U+2028 and U+2029 are escaped too, for older
// JavaScript parsers. The JSON reads back unchanged.
inline std::string ScriptJson(const std::string& json) {
  std::string out;
  out.reserve(json.size());
  for (size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (c == '<') {
      out += "\\u003c";
    } else if (c == '>') {
      out += "\\u003e";
    } else if (c == '&') {
      out += "\\u0026";
    } else if (c == '\xe2' && i + 2 < json.size() && json[i + 1] == '\x80' &&
               (json[i + 2] == '\xa8' || json[i + 2] == '\xa9')) {
      out += json[i + 2] == '\xa8' ? "\\u2028" : "\\u2029";
      i += 2;
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace hexgait
