# TESTBED_SANITIZE=ON: every target of the build compiled and linked with AddressSanitizer
# and UndefinedBehaviorSanitizer (scripts/sanitize.sh, docs/input-limits.md "Sanitizers"). Undefined
# behaviour aborts instead of printing and going on, so a test that meets it fails.
# Plugins are shared libraries: they get the same flags, and the executable that loads
# them carries the ASan runtime.
set(testbed_sanitize_flags
  -fsanitize=address,undefined
  -fno-sanitize-recover=undefined
  -fno-omit-frame-pointer)
add_compile_options(${testbed_sanitize_flags})
add_link_options(${testbed_sanitize_flags})
