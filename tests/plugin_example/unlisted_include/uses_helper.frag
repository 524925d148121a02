#version 450 core
// Build-check fixture (tests/plugin_example/CMakeLists.txt): includes a helper of its own
// that its SHADERS list leaves out, which must stop the build at this line (6).
#include "testbed/glsl/receiver.glsl"

#include "tests/plugin_example/unlisted_include/helper.glsl"
