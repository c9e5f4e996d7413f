#!/bin/bash
# The CUDA checks in one call, from a folder made by gpu/kit.sh: the device, the CPU<->CUDA
# identity test (with backend selection), the analytic shapes host against device, then the
# benchmarks of the CUDA issue (frames at 512² and 1024² on both backends; on the GPU again
# with SHEAF_CUDA_PINNED=0, and keeping only the combined pass; the profile of two office
# and two cornell frames at 512², the second finding the scene on the device; paper 003's AO
# study at 1024², 16 rays per pixel, on the GPU, culling large meshes in runs, the default,
# with the CPU's 4M-pair traversal batch beside the device's own, and whole objects as the
# paper does, cull.cluster=0). Logs go to OUT_DIR (default $OUT, else ./kit-out); the tables last. The
# steps' time limits add up to 570 s, under the device tool's 600 s per call.
# usage: run.sh [OUT_DIR]
set -u
kit=$(dirname "$(realpath "$0")")
out=${1:-${OUT:-./kit-out}}
mkdir -p "$out"
export LD_LIBRARY_PATH="$kit/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export SHEAF_CUDA_MODULE="$kit/lib/libsheaf_cuda.so.0"
export SHEAF_SCENES_DIR="$kit/scenes" SHEAF_POV_INCLUDE="$kit/pov-include"
# Every launch synchronous for the test, so a fault names the launch that made it.
(nvidia-smi -L; nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv) \
  >"$out/device.txt" 2>&1
cat "$out/device.txt"
SHEAF_CUDA_SYNC=1 timeout 140 "$kit/bin/sheaf_cuda_tests" >"$out/cuda_tests.txt" 2>&1
echo "cuda tests: exit $? ($(grep -c '^\[       OK' "$out/cuda_tests.txt") ok," \
     "$(grep -c '^\[  FAILED  \]' "$out/cuda_tests.txt") failed lines)"
grep -E '^\[  (FAILED|SKIPPED) |^module ' "$out/cuda_tests.txt" | head -20
# Analytic shapes ray by ray, and isosurfaces step by step: where host and device part.
timeout 40 "$kit/bin/sheaf_cuda_bits_tests" >"$out/cuda_bits.txt" 2>&1
echo "cuda bits test: exit $?"
grep -v -E '^\[ |^Running main|^Note: ' "$out/cuda_bits.txt" | head -40
timeout 130 "$kit/bin/sheaf_frame_bench" --frames 5 >"$out/frame_bench.md" 2>&1
echo "frame bench: exit $?"
# The same frames on the GPU with the page-locked staging of large copies off, to compare.
SHEAF_CUDA_PINNED=0 timeout 30 "$kit/bin/sheaf_frame_bench" --frames 5 --backends cuda \
  >"$out/frame_bench_pageable.md" 2>&1
echo "frame bench, pageable copies: exit $?"
# And reading back only the image (output.passes=combined), as a viewer would.
timeout 30 "$kit/bin/sheaf_frame_bench" --frames 5 --backends cuda --set output.passes=combined \
  >"$out/frame_bench_combined.md" 2>&1
echo "frame bench, combined pass only: exit $?"
# Where office's and cornell's frames go: every span's device and host time, the host's steps.
SHEAF_CUDA_PROFILE=1 timeout 20 "$kit/bin/sheaf_frame_bench" --frames 2 --sizes 512 \
  --backends cuda office cornell >"$out/profile_frames.txt" 2>&1
echo "profile: exit $?"
timeout 110 "$kit/bin/sheaf_ao_study" --backends cuda --frames 3 >"$out/ao_study.md" 2>&1
echo "ao study: exit $?"
# traversal.batch=0 sizes the batch to the device (64M pairs on an H100 or H200); the CPU's 4M.
timeout 30 "$kit/bin/sheaf_ao_study" --backends cuda --sorts radix --set traversal.batch=4194304 \
  >"$out/ao_study_batch4m.md" 2>&1
echo "ao study, 4M-pair batch: exit $?"
timeout 40 "$kit/bin/sheaf_ao_study" --backends cuda --sorts radix --set cull.cluster=0 \
  >"$out/ao_study_whole_objects.md" 2>&1
echo "ao study, whole objects: exit $?"
grep '^profile\|^| ' "$out/profile_frames.txt" | head -120
cat "$out/frame_bench.md" "$out/frame_bench_pageable.md" "$out/frame_bench_combined.md" \
  "$out/ao_study.md" "$out/ao_study_batch4m.md" "$out/ao_study_whole_objects.md"
