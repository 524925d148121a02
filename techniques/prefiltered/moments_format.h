#pragma once
// What distinguishes one pre-filtered technique from another: the texel format of its
// moments and the pair of GLSL entry points (in moments.glsl) that write and read them.
// Everything else (the moments pass, the blur, the screen pass) is shared.
#include <string>

#include "testbed/gl/gl.h"

namespace testbed {

struct MomentsFormat {
  GLenum internalFormat = GL_RG32F;  // GL_R32F, GL_RG32F, GL_RGBA32F or GL_RGBA16
  // `vec4 encode(float z, vec4 params)`: the texel written for linear light depth z.
  std::string encode;
  // `float visibility(vec4 filtered, float t, vec4 params)`: 1 lit .. 0 shadow.
  std::string visibility;

  // The defines that select the entry points in moments.frag and visibility.frag, so
  // those two shaders are written once for every technique.
  std::string defines() const {
    return "#define MOMENTS_ENCODE " + encode + "\n#define MOMENTS_VISIBILITY " + visibility + "\n";
  }
  bool operator==(const MomentsFormat&) const = default;
};

}  // namespace testbed
