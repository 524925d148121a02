#include <cstdlib>

#include <gtest/gtest.h>

int main(int argc, char** argv) {
  // A uniform a shader uses and nobody set is an error in the tests, here and in every
  // testbed they run (which inherit the environment), and a warning for users
  // (testbed/gl/objects.h Program).
  setenv("TESTBED_UNSET_UNIFORMS", "error", 1);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
