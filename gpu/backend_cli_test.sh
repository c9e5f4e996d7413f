#!/bin/bash
# The backend setting through the render CLI: backend=auto renders on the CPU and says why when
# there is no usable CUDA module or device (here: a module path that does not exist, then
# whatever this machine has), backend=cuda without a device fails with exit code 3 and a
# message, -q keeps the line out.
# usage: backend_cli_test.sh RENDER OUTDIR
set -u
render=$1 out=$2
mkdir -p "$out"
fail=0
check() { # name, condition
  if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fail=1; fi
}

SHEAF_CUDA_MODULE=/nonexistent/libsheaf_cuda.so.0 "$render" builtin:cornell -W 16 -H 12 \
  -o "$out/auto.png" --set backend=auto >"$out/auto.out" 2>"$out/auto.err"
rc=$?
check "auto without a module renders" "[ $rc = 0 ] && [ -s '$out/auto.png' ]"
check "auto says cpu in one line" "[ \$(grep -c '^backend: cpu' '$out/auto.err') = 1 ]"

SHEAF_CUDA_MODULE=/nonexistent/libsheaf_cuda.so.0 "$render" builtin:cornell -W 16 -H 12 \
  -o "$out/cuda.png" --set backend=cuda >"$out/cuda.out" 2>"$out/cuda.err"
rc=$?
check "cuda without a module fails with exit code 3" "[ $rc = 3 ]"
check "cuda names the reason" "grep -q 'backend=cuda: .*no CUDA module' '$out/cuda.err'"

SHEAF_CUDA_MODULE=/nonexistent/libsheaf_cuda.so.0 "$render" builtin:cornell -W 16 -H 12 -q \
  -o "$out/quiet.png" >"$out/quiet.out" 2>"$out/quiet.err"
check "-q prints no backend line" "! grep -q '^backend:' '$out/quiet.err'"

# --compare and --sweep: one line with the reason when every run says the same, else each run's.
SHEAF_CUDA_MODULE=/nonexistent/libsheaf_cuda.so.0 "$render" --compare crsh,rah builtin:cornell \
  -W 16 -H 12 >"$out/compare.out" 2>"$out/compare.err"
check "compare says cpu and why in one line" \
  "[ \$(grep -c '^backend: ' '$out/compare.err') = 1 ] && grep -q '^backend: cpu (.*no CUDA module' '$out/compare.err'"
SHEAF_CUDA_MODULE=/nonexistent/libsheaf_cuda.so.0 "$render" --sweep backend=cpu,auto builtin:cornell \
  -W 16 -H 12 >"$out/sweep.out" 2>"$out/sweep.err"
check "sweep names each run's backend and why" \
  "grep -q '^backend: backend=cpu: cpu (backend=cpu); backend=auto: cpu (.*no CUDA module' '$out/sweep.err'"

# This machine as it is: the module of this build (if nvcc was found) and whatever device.
"$render" builtin:cornell -W 16 -H 12 -o "$out/here.png" >"$out/here.out" 2>"$out/here.err"
rc=$?
check "auto renders here" "[ $rc = 0 ]"
check "auto says where" "grep -q -E '^backend: (cpu|cuda)' '$out/here.err'"
"$render" builtin:cornell -W 16 -H 12 -o "$out/here_cuda.png" --set backend=cuda \
  >"$out/here_cuda.out" 2>"$out/here_cuda.err"
rc=$?
if grep -q '^backend: cuda' "$out/here.err"; then
  check "cuda renders where auto chose cuda" "[ $rc = 0 ]"
else
  check "cuda fails here like auto fell back" "[ $rc = 3 ] && grep -q 'backend=cuda' '$out/here_cuda.err'"
fi
for f in auto cuda compare sweep here here_cuda; do echo "--- $f.err"; cat "$out/$f.err"; done
exit $fail
