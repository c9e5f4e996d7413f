#!/usr/bin/env bash
# Runs one fuzzer for a given amount of CPU time, as docs/fuzzing.md's figures were taken:
#   tests/fuzz/run_for_cpu_time.sh BUILD_DIR FORMAT CPU_SECONDS WORK_DIR
# FORMAT is pov, xml, obj, ply, capi, accel or farm. In WORK_DIR/FORMAT: seeds/ (filled here once from the
# sample scenes and the regressions), corpus/, artifacts/ (what it finds: crash-*, timeout-*,
# oom-*, leak-*), log.txt (libFuzzer's), cpu.txt (wall and CPU seconds so far).
# libFuzzer runs in fork mode and keeps going after a finding (-ignore_crashes and the like), so
# one run reports every kind of finding; its processes are niced. It stops once they have used
# CPU_SECONDS of CPU: the parent's, its finished jobs' (counted when they end) and the running
# job's (libFuzzer starts each job through sh, so the fuzzing process is a grandchild).
set -euo pipefail
build=$(cd "$1" && pwd); fmt=$2; budget=$3; work=$4/$2
src=$(cd "$(dirname "$0")/../.." && pwd)
fuzzer=$build/tests/fuzz/fuzz_$fmt
[ -x "$fuzzer" ] || { echo "no $fuzzer: build it as tests/fuzz/README.md says" >&2; exit 2; }
mkdir -p "$work"/{seeds,corpus,artifacts}
if [ -z "$(ls -A "$work/seeds")" ]; then
  case $fmt in
    pov) cp "$src"/scenes/*.pov "$src"/tests/fuzz/regressions/*.pov "$work/seeds/" ;;
    xml) cp "$src"/scenes/*.xml "$src"/tests/fuzz/regressions/*.xml "$work/seeds/" ;;
    obj) cp "$src"/scenes/*.obj "$src"/tests/fuzz/regressions/*.obj "$work/seeds/" ;;
    ply) cp "$src"/tests/fuzz/regressions/*.ply "$work/seeds/" ;;
    capi) cp "$src"/tests/fuzz/regressions/*.capi "$work/seeds/" ;;
    accel) cp "$src"/tests/fuzz/regressions/*.accel "$work/seeds/" ;;
    farm) cp "$src"/tests/fuzz/regressions/*.farm "$work/seeds/" ;;
    *) echo "unknown format $fmt (pov, xml, obj, ply, capi, accel, farm)" >&2; exit 2 ;;
  esac
fi
extra=()
[ "$fmt" = pov ] && extra+=("-dict=$src/tests/fuzz/pov.dict")
maxlen=65536; [ "$fmt" = capi ] && maxlen=4096; [ "$fmt" = accel ] && maxlen=8192
cd "$work"
start=$(date +%s)
nice -n 10 "$fuzzer" "${extra[@]}" -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
  -timeout=20 -rss_limit_mb=4096 -max_len=$maxlen -artifact_prefix="$work/artifacts/" \
  -print_final_stats=1 corpus seeds > log.txt 2>&1 &
pid=$!
ticks=$(getconf CLK_TCK)
descendants() { for c in $(pgrep -P "$1" || true); do echo "$c"; descendants "$c"; done; }
while kill -0 $pid 2>/dev/null; do
  sleep 15
  stat=$(cat /proc/$pid/stat 2>/dev/null) || break
  # utime, stime, cutime, cstime: fields 14-17 (the name, field 2, has no spaces here)
  cpu=$(echo "$stat" | awk '{print $14 + $15 + $16 + $17}')
  for c in $(descendants $pid); do
    cpu=$((cpu + $(awk '{print $14 + $15}' /proc/$c/stat 2>/dev/null || echo 0)))
  done
  echo "wall $(($(date +%s) - start)) s, cpu $((cpu / ticks)) s" > cpu.txt
  if [ $((cpu / ticks)) -ge "$budget" ]; then
    kill -INT $pid; sleep 20; kill $pid 2>/dev/null || true
  fi
done
wait $pid 2>/dev/null || true
echo "finished" >> cpu.txt
