#!/bin/sh
# A bad value of one of testbed_benchmarks' own flags: exit 2 and one line on stderr that
# names the flag, before any context is created or any benchmark runs.
# Usage: bad_flags_test.sh path/to/testbed_benchmarks
binary=$1
failed=0
check() {  # check FLAG ARGUMENT...
  flag=$1
  shift
  err=$("$binary" "$@" 2>&1 >/dev/null)
  status=$?
  lines=$(printf '%s\n' "$err" | wc -l)
  case "$err" in
    *"$flag"*) named=yes ;;
    *) named=no ;;
  esac
  if [ "$status" -ne 2 ] || [ "$lines" -ne 1 ] || [ "$named" != yes ]; then
    echo "FAIL: $* -> exit $status, $lines line(s), flag named: $named: $err"
    failed=1
  else
    echo "ok: $* -> $err"
  fi
}
check --size --size=abc
check --size --size=1280
check --size --size=0x720
check --size --size=1280x-5
check --size --size=12x34x5
check --shadow-maps --shadow-maps=-3
check --shadow-maps --shadow-maps=512,abc
check --shadow-maps --shadow-maps=512,
check --shadow-maps --shadow-maps=99999999999999
check --scenes --scenes=/nonexistent/scenes
check --backend --backend=bogus --size=16x16 --shadow-maps=16 --benchmark_filter=none
exit $failed
