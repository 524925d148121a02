#pragma once
// Text from users and plugins (spec labels, titles and citations, scene names, pass names,
// backends, technique citations) set into Markdown: escaped so that it reads as itself
// instead of being refused. Every Markdown the testbed writes takes such text through
// these two functions. In a GitHub-flavoured table a '|' would split the cell and a line
// break end the table (or, at a line's start, make a heading or list of the rest); a
// backtick would open a code span, '<' raw HTML.
#include <algorithm>
#include <cctype>
#include <string>

namespace testbed {

namespace markdown_detail {
inline bool wordAt(const std::string& text, std::size_t i) {  // i may be npos or the end
  return i < text.size() && std::isalnum(static_cast<unsigned char>(text[i]));
}
}  // namespace markdown_detail

inline std::string markdownText(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == '\\' || c == '|' || c == '`' || c == '*' || c == '~' || c == '[' || c == ']' ||
        (c == '_' && !(markdown_detail::wordAt(text, i - 1) && markdown_detail::wordAt(text, i + 1)))) {  // "a_b" never emphasizes
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

// `text` as an inline code span (CommonMark 6.1): fenced by more backticks than its longest
// run of them, line breaks and control characters as spaces; '|' stays escaped, since a
// GitHub-flavoured table splits cells before it reads code spans.
inline std::string markdownCode(const std::string& text) {
  std::string body;
  std::size_t run = 0, longest = 0;
  for (const char ch : text) {
    const unsigned char c = static_cast<unsigned char>(ch);
    run = c == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
    if (c == '|') body += "\\|";
    else if (c < 0x20 || c == 0x7f) body += ' ';
    else body += ch;
  }
  const std::string fence(longest + 1, '`');
  // A space on each side where the text begins or ends with a backtick (the reader strips one).
  const bool pad = !body.empty() && (body.front() == '`' || body.back() == '`');
  return fence + (pad ? " " : "") + body + (pad ? " " : "") + fence;
}

}  // namespace testbed
