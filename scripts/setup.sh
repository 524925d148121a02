#!/usr/bin/env bash
# Prepares a Debian 12 machine for the testbed, idempotently:
#   1. installs the Debian packages the build needs (apt-get; sudo when not root),
#   2. extracts the asset meshes from Debian's libcgal-demo data into assets/,
#   3. configures and builds (Release) into build/,
#   4. builds the libFuzzer harnesses with clang into build-fuzz/ (their smoke run is in the suite).
# Every step is skipped when it is already done, so the README commands stay cheap.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${TESTBED_BUILD_DIR:-$repo/build}"
fuzz_dir="${TESTBED_FUZZ_BUILD_DIR:-$repo/build-fuzz}"
asset_dir="$repo/assets"

packages=(
  build-essential cmake ninja-build pkg-config python3
  libosmesa6-dev libegl-dev libegl1-mesa-dev libgl-dev libglfw3-dev
  python3-glad libglm-dev libopenmesh-dev libopenimageio-dev openimageio-tools
  libcli11-dev nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev
  libembree-dev libcgal-demo assimp-testmodels fonts-dejavu-core
  libimgui-dev libglx-mesa0 libgl1-mesa-dri xvfb
  python3-matplotlib python3-scipy python3-numpy python3-pil slurm-wlm munge ffmpeg
  chromium chromium-driver python3-selenium glslang-tools glslang-dev
  clang libclang-rt-dev
)

log() { echo "setup: $*" >&2; }

install_packages() {
  local missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  log "installing ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

# Asset name → file inside libcgal-demo's data archive. Scenes name meshes by asset name.
declare -A assets=(
  [bunny]=bunny00.off
  [armadillo]=armadillo.off
  [dragon]=ChineseDragon-10kv.off
  [elephant]=elephant.off
  [elephant-with-holes]=elephant-with-holes.off
  [cow]=cow.off
  [knot]=knot1.off
  [fandisk]=fandisk.off
  [bear]=bear.off
)

extract_assets() {
  local archive=/usr/share/doc/libcgal-dev/data.tar.gz
  local missing=0
  for name in "${!assets[@]}"; do [ -s "$asset_dir/$name.off" ] || missing=1; done
  [ $missing -eq 0 ] && return 0
  [ -f "$archive" ] || { log "error: $archive not found (package libcgal-demo)"; exit 1; }
  log "extracting asset meshes into $asset_dir"
  local tmp
  tmp="$(mktemp -d)"
  local members=()
  for name in "${!assets[@]}"; do members+=("data/meshes/${assets[$name]}"); done
  tar -xzf "$archive" -C "$tmp" "${members[@]}"
  mkdir -p "$asset_dir"
  for name in "${!assets[@]}"; do mv "$tmp/data/meshes/${assets[$name]}" "$asset_dir/$name.off"; done
  rm -rf "$tmp"
}

build() {
  if [ ! -f "$build_dir/build.ninja" ]; then
    log "configuring $build_dir"
    # A fresh build compiles in batches (docs/performance.md "Build time").
    cmake -S "$repo" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DTESTBED_UNITY_BUILD=ON >/dev/null
  fi
  log "building $build_dir"
  # Ninja's progress lines are hidden; warnings, errors and the build's status are not.
  set +o pipefail
  cmake --build "$build_dir" -- -j"$(nproc)" 2>&1 | { grep -vE '^\[[0-9]+/[0-9]+\] |^ninja: no work' || true; }
  local status=${PIPESTATUS[0]}
  set -o pipefail
  return "$status"
}

# The fuzz harnesses compile only their parsers' sources, with clang, libFuzzer and the
# sanitizers (fuzz/CMakeLists.txt), so this build is small; the suite runs their smoke run.
build_fuzzers() {
  if [ ! -f "$fuzz_dir/build.ninja" ]; then
    log "configuring $fuzz_dir"
    CC=clang CXX=clang++ cmake -S "$repo" -B "$fuzz_dir" -G Ninja -DTESTBED_WITH_FUZZERS=ON \
      -DTESTBED_WITH_TESTS=OFF -DTESTBED_WITH_BENCHMARKS=OFF -DTESTBED_WITH_VIEWER=OFF \
      -DTESTBED_WITH_EMBREE=OFF >/dev/null
  fi
  log "building $fuzz_dir"
  set +o pipefail
  cmake --build "$fuzz_dir" --target fuzzers -- -j"$(nproc)" 2>&1 | { grep -vE '^\[[0-9]+/[0-9]+\] |^ninja: no work' || true; }
  local status=${PIPESTATUS[0]}
  set -o pipefail
  return "$status"
}

install_packages
extract_assets
build
build_fuzzers
