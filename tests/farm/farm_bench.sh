#!/usr/bin/env bash
# The farm's costs on a one-node Slurm cluster (slurm_cluster.sh), as a table:
#  - the overhead per task: 16 empty tasks (`true`) from sbatch to the last one done, and 16
#    farm tasks that render next to nothing (a 4x4-pixel tile each), submit to merge done;
#  - a 16-tile frame through the farm against the same frame in one process.
# Usage: farm_bench.sh PATH/TO/render [SCENE ARGS...]   (default: builtin:office 640x480 +A)
# Not a test: the figures go to docs/farm.md. Needs Slurm and munge (apt-get install
# slurmctld slurmd slurm-client munge).
set -eu

RENDER=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
shift
SCENE=("$@")
[ ${#SCENE[@]} -gt 0 ] || SCENE=(builtin:office -W 640 -H 480 +A)
HERE=$(cd "$(dirname "$0")" && pwd)
"$HERE/slurm_cluster.sh" available
WORK=$(mktemp -d /tmp/sheaf-bench.XXXXXX)
trap '"$HERE/slurm_cluster.sh" stop "$WORK/c" >/dev/null 2>&1; rm -rf "$WORK"' EXIT
eval "$("$HERE/slurm_cluster.sh" start "$WORK/c")"
cpus=$(sinfo -h -o %c)

now() { date +%s.%N; }
elapsed() { awk -v a="$(now)" -v b="$1" 'BEGIN { printf "%.3f", a - b }'; }

# 16 empty tasks, sbatch to the last one leaving the queue.
t=$(now)
id=$(sbatch --parsable --array=1-16 -o /dev/null --wrap true)
while [ -n "$(squeue -h -j "$id" 2>/dev/null)" ]; do sleep 0.05; done
empty=$(elapsed "$t")

# 16 farm tasks of a 16x16 frame: each a 4x4 tile; submit to merge done.
t=$(now)
"$RENDER" builtin:cornell -W 16 -H 16 --farm slurm --farm-tiles 16 --farm-dir "$WORK/tiny" \
    -o "$WORK/tiny.png" --farm-wait -q >/dev/null
tiny=$(elapsed "$t")

# The frame in one process, then in 16 tiles through the farm.
t=$(now)
"$RENDER" "${SCENE[@]}" -q -o "$WORK/one.png"
one=$(elapsed "$t")
t=$(now)
"$RENDER" "${SCENE[@]}" --farm slurm --farm-tiles 16 --farm-dir "$WORK/tiles" \
    -o "$WORK/tiles.png" --farm-wait -q >/dev/null
tiles=$(elapsed "$t")
idiff -a "$WORK/one.png" "$WORK/tiles.png" >/dev/null && same=yes || same=NO

printf '%-52s %10s %12s\n' "on a one-node cluster, $cpus CPUs" "wall s" "s per task"
printf '%-52s %10.2f %12.2f\n' "16 empty tasks (sbatch --array=1-16 --wrap true)" "$empty" "$(awk -v t="$empty" 'BEGIN { print t / 16 }')"
printf '%-52s %10.2f %12.2f\n' "16 farm tasks, 4x4-pixel tiles, and the merge" "$tiny" "$(awk -v t="$tiny" 'BEGIN { print t / 16 }')"
printf '%-52s %10.2f\n' "${SCENE[*]}: one process" "$one"
printf '%-52s %10.2f %12.2f\n' "${SCENE[*]}: 16 tiles and the merge" "$tiles" "$(awk -v t="$tiles" 'BEGIN { print t / 16 }')"
echo "tiles merged equal the one-process frame: $same"
