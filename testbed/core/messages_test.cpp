#include "testbed/core/messages.h"

#include <iostream>
#include <sstream>

#include <gtest/gtest.h>

namespace testbed {
namespace {

TEST(Messages, OneLineEscapesControlCharactersAndKeepsUtf8) {
  EXPECT_EQ(oneLine("scenes/a\nb.json"), "scenes/a\\nb.json");
  EXPECT_EQ(oneLine("tab\there\r"), "tab\\there\\r");
  EXPECT_EQ(oneLine(std::string("nul\0bell\a", 9)), "nul\\x00bell\\x07");
  EXPECT_EQ(oneLine("shadow map 1024²"), "shadow map 1024²");
}

// A failure in the middle of a progress line starts its message on a line of its own.
TEST(Messages, AnOpenProgressLineIsEndedBeforeAnError) {
  std::ostringstream captured;
  std::streambuf* original = std::cerr.rdbuf(captured.rdbuf());
  beginProgressLine("[1/2] sm on wall");
  endProgressLine(": 1 ms");
  beginProgressLine("[2/2] pcf on\nwall");
  breakProgressLine();
  std::cerr << "testbed: error: x\n";
  breakProgressLine();  // nothing open: nothing written
  std::cerr.rdbuf(original);
  EXPECT_EQ(captured.str(), "[1/2] sm on wall: 1 ms\n[2/2] pcf on\\nwall\ntestbed: error: x\n");
}

}  // namespace
}  // namespace testbed
