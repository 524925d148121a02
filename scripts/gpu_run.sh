#!/usr/bin/env bash
# Runs the testbed on a GPU machine through EGL (docs/gpu.md), from the root of a checkout
# that holds .gpu/bundle.tar.xz (scripts/gpu_bundle.sh, with the test binary as extra ELF)
# and the asset meshes in assets/. In order, each step bounded so the whole run ends near
# $GPU_RUN_SECONDS (default 450):
#   1. the machine: nvidia-smi, the EGL vendor, the GL renderer;
#   2. every paper spec (paper/*.json, GI 2016 first) through `testbed sweep --backend egl`,
#      sequentially: shards in parallel would share the GPU and corrupt each other's timings;
#   3. `testbed compare --backend egl --repeat 3` on every bundled scene at 1024² (as
#      scripts/results.sh makes results/<scene>-1024 on llvmpipe);
#   4. the GL tests (GoogleTest) with TESTBED_TEST_BACKEND=egl and the Embree cross-check.
# Everything lands in $OUT (default ./gpu-out): run.log, one tarball per step.
# GPU_RUN_SPECS="gi2016-table2 ..." runs only those specs.
# The binaries were built in /work/main (TESTBED_SOURCE_DIR: sweep_plot.py, test data), so
# this checkout is linked there when that path is free.
set -uo pipefail
export PYTHONUNBUFFERED=1
repo="$(pwd)"
out="${OUT:-$repo/gpu-out}"
mkdir -p "$out"
exec > >(tee -a "$out/run.log") 2>&1
start=$SECONDS
deadline=$((start + ${GPU_RUN_SECONDS:-450}))
left() { echo $((deadline - SECONDS)); }
step() { echo "== [$((SECONDS - start)) s] $*"; }

step "setup"
if [ ! -e /work/main ]; then mkdir -p /work && ln -s "$repo" /work/main; fi
for f in .gl/*.deb; do [ -f "$f" ] && dpkg -x "$f" /; done
ldconfig
rm -rf /tmp/tb && mkdir -p /tmp/tb && tar -C /tmp/tb -xJf .gpu/bundle.tar.xz
export LD_LIBRARY_PATH=/tmp/tb/bundle/lib
export TESTBED_ASSET_DIR="$repo/assets"
tb=/tmp/tb/bundle/bin/testbed
if ! "$tb" list > /dev/null 2>&1; then
  echo "testbed does not start with the system's libstdc++; adding the bundle's"
  export LD_LIBRARY_PATH=/tmp/tb/bundle/lib:/tmp/tb/bundle/lib-fallback
fi
if python3 -c "import matplotlib" 2> /dev/null; then export TESTBED_PYTHON="$(command -v python3)"; plot=()
else echo "no matplotlib: sweeps run with --no-plot"; plot=(--no-plot); fi
nvidia-smi -L
nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm --format=csv
uname -r; grep -m1 "model name" /proc/cpuinfo; nproc

step "EGL context"
mkdir -p "$out/probe"
probe() { timeout 60 "$tb" render --scene scenes/wall.json --technique sm --backend egl \
  --size 320x180 --shadow-map 256 --out "$out/probe"; }
if ! probe; then
  echo "no EGL display with the default vendor search; naming NVIDIA's vendor file"
  export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
  probe || echo "EGL still fails"
fi
grep -h '"backend"' "$out"/probe/*.json | head -1

step "paper specs"
mkdir -p /tmp/res/paper
specs=(gi2016-figure9 gi2016-table2 gi2016-table3 gi2016-table4 edtsm-star-table4
       edtsm-star-table1 edtsm-star-table2 edtsm-star-table3 gi2016-table5)
[ -n "${GPU_RUN_SPECS:-}" ] && read -r -a specs <<< "$GPU_RUN_SPECS"
sweep_end=$((deadline - 120))
for name in "${specs[@]}"; do
  budget=$((sweep_end - SECONDS))
  if [ "$budget" -lt 10 ]; then echo "skipped $name: out of time"; continue; fi
  step "sweep $name (at most $budget s)"
  timeout "$budget" "$tb" sweep --spec "paper/$name.json" --backend egl "${plot[@]}" \
    --out "/tmp/res/paper/$name" || echo "sweep $name: exit $?"
done
tar -C /tmp/res -cJf "$out/paper.tar.xz" paper

step "compare on every bundled scene"
mkdir -p /tmp/res/compare
for scene in scenes/*.json; do
  name="$(basename "$scene" .json)"
  budget=$(( $(left) - 60 ))
  if [ "$budget" -lt 10 ]; then echo "skipped compare $name: out of time"; continue; fi
  timeout "$budget" "$tb" compare --scene "$scene" --shadow-map 1024 --repeat 3 --backend egl \
    --out "/tmp/res/compare/$name-1024" || echo "compare $name: exit $?"
done
# What scripts/results.sh keeps: the frames' EXRs would pass the 16 MiB a file can bring back.
(cd /tmp/res && find compare \( -name report.md -o -name metrics.json -o -name grid.png \
  -o -name speed_vs_error.svg \) -print0 | tar --null -T - -cJf "$out/compare.tar.xz")

step "GL tests through EGL"
suites='*BlurGlsl*:*DepthPass*:*Edtsm*:*EsmGlsl*:*EvsmGlsl*:*FacingRule*:*FeatureTransform*:*GlObjects*:*Grazing*:*HostileParameters*:*LightFrustumConventionGl*:*LightSetupHardCases*:*MetricsOnScenes*:*MsmGlsl*:*Pcf*:*Prefiltered*:*RecordFromFrames*:*RenderTargets*:*Revectorization*:*SampledTexels*:*SeparableBlur*:*ShaderLibrary*:*ShadowMapAnalytic*:*SilhouetteEdges*:*SilhouetteMap*:*SmsrTwoPass*:*SweepPaperSpecs*:*VsmGlsl*:*RayCast*'
budget=$(( $(left) - 5 ))
if [ "$budget" -ge 10 ]; then
  TESTBED_TEST_BACKEND=egl timeout "$budget" /tmp/tb/bundle/bin/testbed_tests \
    --gtest_filter="$suites" --gtest_output="xml:$out/gl_tests.xml" 2>&1 | tail -n 200 \
    || echo "GL tests: exit $?"
else
  echo "skipped GL tests: out of time"
fi
step "done"
