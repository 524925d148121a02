#pragma once
// Errors the user can fix (bad scene, bad parameter, missing file) versus bugs.
#include <stdexcept>
#include <string>

namespace testbed {

// Bad input: reported as one line "testbed: <where>: <what>" with exit code 2. The message
// names the file and the field, e.g. "scenes/x.json: objects[1].scale: expected a number".
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Failures of the GL environment (no context, shader compile error, GL error).
class GlError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace testbed
