#pragma once

#include <cstddef>
#include <string>

#include "testbed/metrics/metrics.h"

// Rules every metric shares, so the still and the temporal metrics decide alike.
namespace testbed::pixel_rules {

// The hard decision: a visibility of at least one half counts as lit.
inline bool isLit(float value) { return value >= 0.5f; }

// A share in percent; an empty denominator scores 0 (the record carries the denominator).
inline double percent(std::size_t part, std::size_t whole) {
  return whole == 0 ? 0.0 : 100.0 * double(part) / double(whole);
}

inline std::string sizeText(const ImageF& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height);
}

}  // namespace testbed::pixel_rules
