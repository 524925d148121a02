#!/usr/bin/env bash
# Packs a built testbed into a self-contained tarball for a GPU machine that runs another
# distribution (docs/gpu.md): the binaries, every shared library they load except glibc,
# libstdc++ and the GL/EGL dispatch libraries the GPU machine provides (libstdc++ and
# libgcc_s travel in lib-fallback/ for an older system), and stand-ins (scripts/gpu_stubs.py)
# for the libraries only the osmesa backend, the viewer and
# OpenImageIO's exotic formats use, whose trees would weigh some 500 MB.
# Usage: scripts/gpu_bundle.sh OUT.tar.xz [EXTRA_ELF...]   (EXTRA_ELF: e.g. the test binary)
# The tarball unpacks to bundle/{bin,lib,lib-fallback}; bin/ keeps the build's file names.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TESTBED_BUILD_DIR:-$repo/build}"
[ $# -ge 1 ] || { echo "usage: $0 OUT.tar.xz [EXTRA_ELF...]" >&2; exit 2; }
out="$(realpath -m "$1")"; shift
elves=("$build/testbed/app/testbed" "$@")

# Dropped from the closure: provided by any Linux system or by the GPU driver's glvnd.
system='^(libc|libm|libpthread|libdl|librt|libresolv|ld-linux-x86-64|libEGL|libGL|libGLX|libOpenGL|libGLdispatch|libGLESv2)\.so'
fallback='^(libstdc\+\+|libgcc_s)\.so'
stubbed='^(libOSMesa|libglfw|libopencv_(core|imgproc|videoio)|libav(codec|format|util)|libswscale|libopenvdb|libheif|libdcm(image|imgle|data)|liboflog|libofstd|libraw_r)\.so'

stage="$(mktemp -d)"
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/bundle/bin" "$stage/bundle/lib" "$stage/bundle/lib-fallback"
cp "${elves[@]}" "$stage/bundle/bin/"

# Breadth-first over NEEDED, resolved with the build machine's loader cache; a stand-in's
# own dependencies are never visited.
declare -A path_of
while read -r so arrow path _; do
  [ "$arrow" = "=>" ] && [ -z "${path_of[$so]:-}" ] && path_of[$so]="$path"
done < <(ldconfig -p | sed -n 's/^\t\([^ ]*\) (libc6,x86-64[^)]*) \(=>\) \(.*\)$/\1 \2 \3/p')
kept=() stubs=() queue=("${elves[@]}")
declare -A seen
while [ ${#queue[@]} -gt 0 ]; do
  elf="${queue[0]}"; queue=("${queue[@]:1}")
  for so in $(readelf -d "$elf" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'); do
    [ -n "${seen[$so]:-}" ] && continue
    seen[$so]=1
    [[ $so =~ $system ]] && continue
    lib="${path_of[$so]:-}"
    [ -n "$lib" ] || { echo "gpu_bundle: $so (needed by $elf) not found" >&2; exit 1; }
    if [[ $so =~ $fallback ]]; then cp -L "$lib" "$stage/bundle/lib-fallback/$so"
    elif [[ $so =~ $stubbed ]]; then stubs+=("$lib")
    else cp -L "$lib" "$stage/bundle/lib/$so"; kept+=("$stage/bundle/lib/$so"); queue+=("$lib")
    fi
  done
done
python3 "$repo/scripts/gpu_stubs.py" "$stage/bundle/lib" "${elves[@]}" "${kept[@]}" -- "${stubs[@]}"
mkdir -p "$(dirname "$out")"
tar -C "$stage" -cJf "$out.tmp" bundle
mv "$out.tmp" "$out"
echo "gpu_bundle: $out ($(du -h "$out" | cut -f1); ${#kept[@]} libraries, ${#stubs[@]} stand-ins)" >&2
