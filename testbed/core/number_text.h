#pragma once
// The one rule for reading a number from text (options, `--set` values, `--frames`, sizes,
// shards, viewer scripts): the whole text is the number — no spaces, no leading '+', no base
// prefix, no trailing characters, not empty — and it fits the type. std::from_chars gives
// that rule without the locale, so "0x10", "1e3" (for an integer) and " 1" are refused
// rather than read in part.
#include <charconv>
#include <optional>
#include <string_view>
#include <system_error>

namespace testbed {

template <class Number>
std::optional<Number> wholeNumber(std::string_view text) {
  Number value{};
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end) return std::nullopt;
  return value;
}

}  // namespace testbed
