#pragma once
// Text from users (spec labels, scene names) set into Markdown: escaped so that it reads as
// itself instead of being refused. In a GitHub-flavoured table a '|' would split the cell
// and a line break end the table; a backtick would open a code span, '<' raw HTML.
#include <string>

namespace testbed {

inline std::string markdownText(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == '\\' || c == '|' || c == '`') {
      out += '\\';
      out += char(c);
    } else if (c == '<') {
      out += "&lt;";
    } else if (c == '\n') {
      out += "<br>";  // a line break inside a cell, as GitHub renders tables
    } else if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') {
      // part of a CRLF line break: the '\n' gives the <br>
    } else if (c < 0x20 || c == 0x7f) {
      out += ' ';
    } else {
      out += char(c);
    }
  }
  return out;
}

}  // namespace testbed
