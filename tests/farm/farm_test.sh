#!/usr/bin/env bash
# Farm jobs end to end on a one-node Slurm cluster (slurm_cluster.sh), each result checked
# against the same work done in one process:
#  - an animation of 8 frames, a task per frame: every frame equal, pixel for pixel (idiff);
#  - a 4x4-tiled frame with anti-aliasing: the merged frame equal to the one-process frame;
#  - a 2x2 sweep: the merged results.json equal to a one-process sweep's (times aside);
#  - a task killed midway: requeued by Slurm, and the result still exact;
#  - a second submission of a finished job: no task runs;
#  - a task failing in the scene: the job stops with that reason;
#  - a state record that is a device: --farm-status refuses it rather than read it.
# Usage: farm_test.sh PATH/TO/render OUTPUT_DIR. Exits 77 (skip) without Slurm and munge.
set -u

RENDER=${1:?usage: farm_test.sh RENDER OUTDIR}
OUT=${2:?usage: farm_test.sh RENDER OUTDIR}
HERE=$(cd "$(dirname "$0")" && pwd)
"$HERE/slurm_cluster.sh" available || exit 77
command -v idiff >/dev/null || { echo "idiff (openimageio-tools) is missing"; exit 77; }
rm -rf "$OUT"
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)

. "$HERE/../lib/checks.sh"

# The cluster's folder: short (munge's socket path is limited), removed at the end.
CLUSTER=$(mktemp -d /tmp/sheaf-farm.XXXXXX)
stop_cluster() { "$HERE/slurm_cluster.sh" stop "$CLUSTER" >/dev/null 2>&1; rm -rf "$CLUSTER"; }
trap stop_cluster EXIT
# Four CPUs declared: more tasks at once than the two cores here, as on a real node.
if ! started=$(SHEAF_SLURM_CPUS=4 "$HERE/slurm_cluster.sh" start "$CLUSTER" 2>"$OUT/cluster.err"); then
    echo "the one-node cluster did not start:"
    cat "$OUT/cluster.err"
    exit 1
fi
eval "$started"

# same_pixels A B WHAT: idiff finds no difference.
same_pixels() {
    if idiff -a "$1" "$2" >"$OUT/idiff.out" 2>&1; then pass "$3"; else fail "$3: $(tail -2 "$OUT/idiff.out")"; fi
}

# wait_job DIR NAME ARGS...: submits with --farm-wait (bounded), keeping the exit code in $rc.
submit() {
    local name=$1
    shift
    timeout 300 "$RENDER" "$@" --farm slurm --farm-wait >"$OUT/$name.out" 2>"$OUT/$name.err"
    rc=$?
}

# ---- An animation of 8 frames, one task each.
cat >"$OUT/clock.pov" <<'POV'
camera { location <0, 1, -9> look_at 0 }
light_source { <3, 5, -4> rgb 1 }
#for (I, 1, frame_number) sphere { <I - 4.5, 0, 0>, 0.4 pigment { rgb <1, clock, 0.5> } } #end
plane { y, -1 pigment { checker rgb 1 rgb 0.2 } finish { reflection 0.3 } }
POV
A=("$OUT/clock.pov" -W 48 -H 32 +KFI1 +KFF8)
mkdir -p "$OUT/one"
"$RENDER" "${A[@]}" -q -o "$OUT/one/f.png" || fail "the one-process animation"
submit anim "${A[@]}" -o "$OUT/anim/f.png" --farm-dir "$OUT/anim_job"
[ "$rc" = 0 ] && pass "the animation's job ends" || fail "animation job: exit $rc: $(cat "$OUT/anim.err")"
expect_in "$OUT/anim.out" "tasks 1-8 of 8" "the animation is an array of 8 tasks"
expect_in "$OUT/anim.out" "8 tasks: 8 done, 0 running, 0 failed, 0 waiting" "the progress reaches 8 done"
for f in 1 2 3 4 5 6 7 8; do
    same_pixels "$OUT/one/f$f.png" "$OUT/anim/f$f.png" "frame $f equals the one-process frame"
done

# ---- A 4x4-tiled frame with anti-aliasing: merged, it equals the frame of one process.
T=(builtin:office -W 96 -H 64 +A --set ao.samples=2)
"$RENDER" "${T[@]}" -q -o "$OUT/one/office.png" || fail "the one-process frame"
submit tiles "${T[@]}" --farm-tiles 16 --farm-dir "$OUT/tiles_job" -o "$OUT/tiles/office.png"
[ "$rc" = 0 ] && pass "the tiled job ends" || fail "tiled job: exit $rc: $(cat "$OUT/tiles.err")"
expect_in "$OUT/tiles.out" "submitted merge job" "a merge job follows the array"
expect_in "$OUT/tiles.out" "merge done" "the progress shows the merge done"
same_pixels "$OUT/one/office.png" "$OUT/tiles/office.png" "16 tiles merged equal the one-process frame"

# ---- A second submission of the finished job runs no task.
submit again "${T[@]}" --farm-tiles 16 --farm-dir "$OUT/tiles_job" -o "$OUT/tiles/office.png"
[ "$rc" = 0 ] && pass "resubmission ends" || fail "resubmission: exit $rc"
expect_in "$OUT/again.out" "nothing to do: all 16 tasks" "a finished job submitted again runs nothing"
if grep -q "submitted" "$OUT/again.out"; then fail "the resubmission submitted jobs"; else pass "no job submitted again"; fi
# A tile cut short is not complete: only that task runs again.
head -c 100 "$OUT/tiles_job/parts/tile-7.exr" >"$OUT/cut.exr" && mv "$OUT/cut.exr" "$OUT/tiles_job/parts/tile-7.exr"
submit resume "${T[@]}" --farm-tiles 16 --farm-dir "$OUT/tiles_job" -o "$OUT/tiles/office.png"
expect_in "$OUT/resume.out" "tasks 7 of 16" "a damaged tile is rendered again, and only it"
same_pixels "$OUT/one/office.png" "$OUT/tiles/office.png" "the resumed job's frame is still exact"

# ---- A 2x2 sweep: the merged results equal a one-process sweep's.
W=(builtin:cornell -W 32 -H 32 --sweep hierarchy.depth=1,2 hierarchy.arity=2,4)
"$RENDER" "${W[@]}" -q --report "$OUT/one/sweep" >/dev/null 2>&1 || fail "the one-process sweep"
submit sweep "${W[@]}" --report "$OUT/sweep" --farm-dir "$OUT/sweep_job"
[ "$rc" = 0 ] && pass "the sweep's job ends" || fail "sweep job: exit $rc: $(cat "$OUT/sweep.err")"
expect_in "$OUT/sweep.out" "tasks 1-4 of 4" "the sweep is an array of 4 tasks"
[ -f "$OUT/sweep/report.html" ] && pass "the merge writes report.html" || fail "no report.html"
check "the sweep's results equal the one-process sweep's" python3 - "$OUT/one/sweep/results.json" "$OUT/sweep/results.json" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
ea, eb = a["entries"], b["entries"]
assert len(ea) == len(eb) == 4, (len(ea), len(eb))
def counts(e):  # what a render computes; times and memory differ from run to run
    return {k: v for k, v in e["stats"].items() if not k.startswith(("time_ms.", "memory."))}
for x, y in zip(ea, eb):
    assert x["name"] == y["name"] and x["grid"] == y["grid"], (x["name"], y["name"])
    assert counts(x) == counts(y), [k for k in counts(x) if counts(x)[k] != counts(y).get(k)]
    # The farm renders each point as an exact OpenEXR part (output.exr=float); the rest agrees.
    y["settings"]["output.exr"] = x["settings"]["output.exr"]
    assert x["settings"] == y["settings"], x["name"]
PY

# ---- A task killed midway is requeued by Slurm, and the result is still exact.
K=(builtin:office -W 480 -H 320 +A --set ao.samples=8)
"$RENDER" "${K[@]}" -q -o "$OUT/one/killed.png" || fail "the one-process frame (kill)"
timeout 300 "$RENDER" "${K[@]}" --farm slurm --farm-tiles 4 --farm-dir "$OUT/kill_job" \
    -o "$OUT/kill/office.png" --farm-wait >"$OUT/kill.out" 2>"$OUT/kill.err" &
waiter=$!
killed=""
for _ in $(seq 600); do # the first task seen running, killed with SIGKILL
    pid=$(pgrep -f -- "--farm-dir $OUT/kill_job --farm-task" | head -1)
    if [ -n "$pid" ]; then
        sleep 0.3
        kill -KILL "$pid" 2>/dev/null && killed=$pid && break
    fi
    sleep 0.05
done
wait $waiter
rc=$?
[ -n "$killed" ] && pass "a running task was killed" || fail "no running task was seen to kill"
[ "$rc" = 0 ] && pass "the job with a killed task ends" || fail "killed-task job: exit $rc: $(cat "$OUT/kill.err")"
if grep -qs "requeued" "$OUT"/kill_job/logs/task-*.log; then pass "the killed task was requeued"; else fail "no task log says requeued"; fi
same_pixels "$OUT/one/killed.png" "$OUT/kill/office.png" "the frame with a retried task equals the one-process frame"

# ---- A task failing in the scene stops the job with its reason.
cat >"$OUT/broken.pov" <<'POV'
camera { location <0, 1, -9> look_at 0 }
light_source { <3, 5, -4> rgb 1 }
#if (frame_number = 3) #error "frame 3 is broken" #end
sphere { 0, 1 pigment { rgb 1 } }
POV
submit broken "$OUT/broken.pov" -W 16 -H 16 +KFI1 +KFF6 -o "$OUT/broken/b.png" --farm-dir "$OUT/broken_job"
[ "$rc" = 3 ] && pass "a job whose task fails ends with exit 3" || fail "broken job: exit $rc"
expect_in "$OUT/broken.err" "task 3: " "the failed task is named"
expect_in "$OUT/broken.err" "frame 3 is broken" "its reason is the scene's"
check "the status shows the failure" grep -q "1 failed" "$OUT/broken.out"

# ---- Usage errors.
expect_rc farm_no_dir 1 builtin:cornell --farm slurm
expect_in "$OUT/farm_no_dir.err" "--farm-dir" "--farm without --farm-dir is refused"
expect_rc farm_bad 1 builtin:cornell --farm pbs --farm-dir "$OUT/x"
expect_in "$OUT/farm_bad.err" "known are: slurm, and none" "an unknown scheduler is named"
expect_rc farm_print 0 builtin:cornell --farm slurm --farm-tiles 4 --farm-dir "$OUT/print_job" \
    --farm-print -o "$OUT/print.png" --farm-throttle 2 --farm-sbatch "--partition=gpu --gres=gpu:1"
expect_in "$OUT/farm_print.out" "--array=1-4%2" "--farm-print shows the throttled array"
expect_in "$OUT/farm_print.out" "'--gres=gpu:1'" "--farm-sbatch options reach sbatch"
expect_in "$OUT/farm_print.out" "--dependency=afterok" "the merge waits for the array"
expect_rc farm_none 0 builtin:cornell -W 16 -H 16 --farm none --farm-tiles 2 --farm-dir "$OUT/none_job" \
    -o "$OUT/none.png"
expect_in "$OUT/farm_none.out" "--farm-task 2" "--farm none prints the tasks' commands"
# Run as another scheduler would: each printed command, then the merge.
none_ok=1
while read -r line; do eval "$line" >/dev/null 2>&1 || none_ok=0; done <"$OUT/farm_none.out"
[ $none_ok = 1 ] && [ -f "$OUT/none.png" ] && pass "the printed commands run the job" || fail "--farm none's commands failed"
"$RENDER" builtin:cornell -W 16 -H 16 -q -o "$OUT/one/none.png"
same_pixels "$OUT/one/none.png" "$OUT/none.png" "a job run by hand equals the one-process frame"
expect_rc farm_status_none 0 --farm-dir "$OUT/none_job" --farm-status
expect_in "$OUT/farm_status_none.out" "2 tasks: 2 done, 0 running, 0 failed, 0 waiting; merge done" "--farm-status counts the tasks"
# A damaged folder: a record that is a device is refused, not read without end.
ln -sf /dev/zero "$OUT/none_job/state/task-2.done"
expect_rc farm_status_device 1 --farm-dir "$OUT/none_job" --farm-status
expect_in "$OUT/farm_status_device.err" "not a regular file" "a record that is a device is refused"
expect_rc farm_other_job 1 builtin:office --farm slurm --farm-tiles 4 --farm-dir "$OUT/print_job" \
    --farm-print -o "$OUT/print.png"
expect_in "$OUT/farm_other_job.err" "holds another job" "a folder holding another job is refused"

finish
