// The README documents what the code does: its technique table is the registry's. It is
// checked, not rewritten: adding a technique includes regenerating the table
// (docs/writing-a-technique.md, "Writing a technique").
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "testbed/technique/registry.h"
#include "testbed_test_paths.h"

namespace testbed {
namespace {

TEST(Readme, TechniqueTableMatchesTheRegistry) {
  std::ifstream file(std::string(TESTBED_SOURCE_DIR) + "/README.md");
  ASSERT_TRUE(file) << "README.md not found";
  std::stringstream text;
  text << file.rdbuf();
  EXPECT_NE(text.str().find(techniqueTableMarkdown()), std::string::npos)
      << "README.md's technique table is stale (docs/writing-a-technique.md \"Writing a technique\", step 5); "
         "paste the output of `build/testbed/app/testbed list --markdown` over it:\n"
      << techniqueTableMarkdown();
}

}  // namespace
}  // namespace testbed
