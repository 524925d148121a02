// The one number rule (core/number_text.h): the whole text is the number and it fits.
#include "testbed/core/number_text.h"

#include <cstdint>
#include <optional>

#include <gtest/gtest.h>

namespace testbed {
namespace {

TEST(WholeNumber, ReadsTheNumbersItShould) {
  EXPECT_EQ(wholeNumber<int>("0"), 0);
  EXPECT_EQ(wholeNumber<int>("-12"), -12);
  EXPECT_EQ(wholeNumber<std::uint64_t>("18446744073709551615"), UINT64_MAX);
  EXPECT_EQ(wholeNumber<double>("1e3"), 1000.0);
  EXPECT_EQ(wholeNumber<float>("-0.5"), -0.5f);
}

TEST(WholeNumber, RefusesPartsSignsPrefixesAndOverflow) {
  for (const char* text : {"", " 1", "1 ", "+1", "0x10", "1e3", "1.5", "1_000", "12a", "--1"})
    EXPECT_EQ(wholeNumber<int>(text), std::nullopt) << text;
  // 2^64 and 2^65 overflow, and an unsigned type takes no minus sign (no wrap-around).
  for (const char* text : {"18446744073709551616", "36893488147419103232", "-1"})
    EXPECT_EQ(wholeNumber<std::uint64_t>(text), std::nullopt) << text;
  for (const char* text : {"", "1e", "nan(", " 2", "1.0f"}) EXPECT_EQ(wholeNumber<double>(text), std::nullopt) << text;
}

}  // namespace
}  // namespace testbed
