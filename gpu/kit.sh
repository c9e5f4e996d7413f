#!/bin/bash
# Packs what the CUDA checks need into one folder that runs on a GPU machine without this
# build's libraries installed (the lent device machine has CUDA but not Debian's OpenColorIO,
# Assimp, oneTBB ...): the module, the CUDA tests, both benchmarks, the sample scenes,
# POV-Ray's includes, and every shared library they need beyond the C/C++ runtime: about
# 55 MiB, under the device tool's 64 MiB carry (the script fails past it). (Not libsheaf and
# the CLI: they linked OpenImageIO, some 350 MB of libraries, when the kit was made, which is
# why the scene readers take their image reader from the host; since ff7a349 OpenImageIO is
# loaded only through the image module. The test checks backend selection itself.)
#
# usage: gpu/kit.sh BUILD_DIR KIT_DIR     (e.g. gpu/kit.sh build build/gpu-kit)
# then, on the GPU machine: KIT_DIR/run.sh [OUT_DIR]   (docs/performance.md, "On a GPU")
set -euo pipefail
build=$(realpath "$1")
kit=$2
src=$(realpath "$(dirname "$0")/..")
module=$build/plugin/capi/libsheaf_cuda.so.0
[ -e "$module" ] || { echo "kit.sh: $module is missing: this build had no nvcc" >&2; exit 1; }
rm -rf "$kit"
mkdir -p "$kit/bin" "$kit/lib" "$kit/scenes" "$kit/pov-include"
cp -L "$module" "$kit/lib/libsheaf_cuda.so.0"
bins=("$build/gpu/sheaf_cuda_tests" "$build/gpu/sheaf_cuda_bits_tests"
      "$build/tests/bench/sheaf_frame_bench" "$build/tests/bench/sheaf_ao_study")
cp "${bins[@]}" "$kit/bin/"
# Shared libraries beyond glibc, libstdc++ and libgcc (newer on the GPU machine's image).
for f in "${bins[@]}"; do
  ldd "$f" | awk '/=> \// {print $3}'
done | sort -u | grep -v -E '/(libc|libm|libstdc\+\+|libgcc_s|libpthread|libdl|librt)\.so' |
  while read -r lib; do cp -L "$lib" "$kit/lib/"; done
cp -r "$src/scenes/." "$kit/scenes/"
if [ -d /usr/share/povray-3.7/include ]; then cp -rL /usr/share/povray-3.7/include/. "$kit/pov-include/"; fi
cp "$src/gpu/kit_run.sh" "$kit/run.sh"
chmod +x "$kit/run.sh"
du -sh "$kit"
# The device tool carries 64 MiB at most: a kit past it cannot reach the GPU machine.
bytes=$(du -sb "$kit" | cut -f1)
if [ "$bytes" -gt $((64 * 1024 * 1024)) ]; then
  echo "kit.sh: $kit is $((bytes / 1048576)) MiB, over the device tool's 64 MiB carry;" \
       "a new library dependency of the kit's programs (ldd $build/gpu/sheaf_cuda_tests)?" >&2
  exit 1
fi
