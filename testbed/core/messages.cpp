#include "testbed/core/messages.h"

#include <cstdio>
#include <iostream>

namespace testbed {
namespace {

bool lineOpen = false;

}  // namespace

std::string oneLine(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else if (byte < 0x20 || byte == 0x7f) {
      char escaped[5];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out;
}

void beginProgressLine(std::string_view step) {
  breakProgressLine();
  std::cerr << oneLine(step) << std::flush;
  lineOpen = true;
}

void endProgressLine(std::string_view result) {
  std::cerr << oneLine(result) << "\n" << std::flush;
  lineOpen = false;
}

void breakProgressLine() {
  if (lineOpen) std::cerr << "\n";
  lineOpen = false;
}

std::string minutesSeconds(double seconds) {
  const long s = seconds > 0 ? long(seconds + 0.5) : 0;
  char text[32];
  std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
  return text;
}

}  // namespace testbed
