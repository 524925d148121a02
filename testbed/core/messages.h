#pragma once
// What the testbed prints on stderr. Every message is one line (docs/bad-input.md "What bad
// input gets"): names from the user (a scene path with a newline in it, a scene "name") are
// escaped, and a progress line left open by a step that failed is ended before the error.
#include <string>
#include <string_view>

namespace testbed {

// `text` with control characters escaped: newline as \n, carriage return \r, tab \t,
// the others \xNN. Bytes from 0x80 (UTF-8) are kept.
std::string oneLine(std::string_view text);

// A progress line written in two parts: the step ("[2/5] pcf on wall") when it starts,
// its result (": 3.1 ms\n") when it ends.
void beginProgressLine(std::string_view step);
void endProgressLine(std::string_view result);
// Ends a line begun and not yet ended (before an error message); otherwise nothing.
void breakProgressLine();

// A duration as progress lines give elapsed time and ETA: "M:SS" (minutes unbounded).
std::string minutesSeconds(double seconds);

}  // namespace testbed
