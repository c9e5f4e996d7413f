#!/usr/bin/env bash
# slurm_cluster.sh -- a throw-away, one-node Slurm cluster on localhost for tests.
#
#   slurm_cluster.sh available     exit 0 if the Slurm/munge binaries exist, else 77
#   slurm_cluster.sh start DIR     start munged + slurmctld + slurmd, everything under DIR;
#                                  prints "export ..." lines for the caller to eval
#   slurm_cluster.sh stop DIR      cancel its jobs, stop the daemons started by `start DIR`
#
# Typical use:
#   tests/farm/slurm_cluster.sh available || exit 77
#   eval "$(tests/farm/slurm_cluster.sh start /tmp/sheaf-slurm.XXXX)"
#   sbatch --wrap true ...
#   tests/farm/slurm_cluster.sh stop /tmp/sheaf-slurm.XXXX
#
# Needs Debian 12's slurmctld slurmd slurm-client munge; no systemd, nothing written
# outside DIR.  Daemons and jobs run as the invoking user (SlurmUser=SlurmdUser=it;
# tested as root).  Ports are random; SHEAF_SLURM_CPUS=N declares N CPUs, not nproc.
set -euo pipefail

PROG=${0##*/}
die() { echo "$PROG: $*" >&2; exit 1; }

# Daemons are in /usr/sbin, which is not always on a non-root PATH.
PATH=$PATH:/usr/sbin:/sbin

BINARIES=(munged slurmctld slurmd sbatch squeue sinfo scontrol scancel)

cmd_available() {
    local b missing=()
    for b in "${BINARIES[@]}"; do command -v "$b" >/dev/null 2>&1 || missing+=("$b"); done
    if ((${#missing[@]})); then
        echo "$PROG: missing ${missing[*]} (apt-get install slurmctld slurmd slurm-client munge)" >&2
        exit 77
    fi
}

# A TCP port not in use (best effort: /proc/net/tcp*; random, so clashes are rare).
port_in_use() {
    local hex
    hex=$(printf ':%04X ' "$1")
    cat /proc/net/tcp /proc/net/tcp6 2>/dev/null | awk '{print $2" "}' | grep -q -- "$hex"
}
free_port() {
    local p
    for _ in $(seq 50); do
        p=$(shuf -i 20000-59999 -n 1)
        port_in_use "$p" || port_in_use $((p + 1)) || { echo "$p"; return; }
    done
    die "no free TCP port found"
}

# Print the pid in DIR/run/NAME.pid if that process is alive and its command line
# names both NAME and DIR, so a recycled pid or another cluster is never signalled.
live_pid() {
    local dir=$1 name=$2 pid cmd
    [[ -s $dir/run/$name.pid ]] || return 0
    pid=$(<"$dir/run/$name.pid")
    [[ $pid =~ ^[0-9]+$ && -r /proc/$pid/cmdline ]] || return 0
    cmd=$(tr '\0' ' ' <"/proc/$pid/cmdline" 2>/dev/null) || return 0
    [[ $cmd == *"$name"*"$dir/"* ]] && echo "$pid"
    return 0
}

# True while a pid exists and is not a zombie (pid 1 of a container may not reap).
alive() { [[ $(ps -o stat= -p "$1" 2>/dev/null) == [^Z]* ]]; }

# SIGTERM the given pids, wait up to 10 s for them to exit, then SIGKILL the rest.
terminate() {
    local pid any
    (($#)) || return 0
    kill -TERM "$@" 2>/dev/null || true
    for _ in $(seq 100); do
        any=0
        for pid; do alive "$pid" && any=1; done
        ((any)) || return 0
        sleep 0.1
    done
    kill -KILL "$@" 2>/dev/null || true
}

dump_logs() {
    local dir=$1 f
    for f in "$dir"/log/munged.log "$dir"/log/slurmctld.log "$dir"/log/slurmd.log; do
        [[ -s $f ]] || continue
        echo "---- tail $f" >&2
        tail -n 25 "$f" >&2
    done
}

cmd_stop() {
    local dir=$1
    [[ -d $dir ]] || die "stop: no such directory $dir"
    dir=$(cd "$dir" && pwd)
    # Cancel remaining jobs first so that no slurmstepd outlives its slurmd.
    if [[ -f $dir/slurm.conf && -s $dir/run/slurmctld.pid ]]; then
        local ids
        ids=$(SLURM_CONF=$dir/slurm.conf timeout 10 squeue -h -o %A 2>/dev/null || true)
        if [[ -n $ids ]]; then
            # shellcheck disable=SC2086
            SLURM_CONF=$dir/slurm.conf timeout 10 scancel $ids 2>/dev/null || true
            for _ in $(seq 50); do
                [[ -z $(SLURM_CONF=$dir/slurm.conf timeout 5 squeue -h -t R,CG -o %A 2>/dev/null) ]] && break
                sleep 0.2
            done
        fi
    fi
    # slurmctld takes a few seconds to save state and exit; stop both Slurm daemons
    # together, and munged last since they authenticate through it until the end.
    # shellcheck disable=SC2046
    terminate $(live_pid "$dir" slurmd) $(live_pid "$dir" slurmctld)
    # shellcheck disable=SC2046
    terminate $(live_pid "$dir" munged)
    rm -f "$dir"/run/*.pid
}

cmd_start() {
    local dir=$1
    cmd_available
    mkdir -p "$dir"
    dir=$(cd "$dir" && pwd)
    [[ -e $dir/slurm.conf ]] && die "start: $dir already holds a cluster (stop it and use a fresh directory)"
    # Unix socket paths are limited to 108 bytes; slurmd puts <node>_<job>.<step> sockets in its spool.
    ((${#dir} <= 70)) || die "start: directory path too long for Unix sockets (${#dir} > 70): $dir"
    # munged wants its socket directory (and the path to it) world-searchable and
    # no directory on the way group/world-writable; the key stays in a 0700 dir.
    chmod 755 "$dir"
    install -d -m 755 "$dir"/{munge,log,run,state,spool,tmp}
    install -d -m 700 "$dir/key"

    # If anything below fails, report the logs and take down what we started.
    trap 'rc=$?; if ((rc)); then echo "$PROG: start failed" >&2; dump_logs "$dir"; cmd_stop "$dir" || true; fi' EXIT

    # --- munge: private key, socket, pid, log, seed --------------------------------
    # --force turns munged's path-permission errors into warnings, e.g. when DIR sits
    # below a 0700 home directory; only root (the job user here) talks to it anyway.
    local sock=$dir/munge/munge.socket
    if command -v mungekey >/dev/null 2>&1; then
        mungekey --create --keyfile="$dir/key/munge.key"
    else
        dd if=/dev/urandom of="$dir/key/munge.key" bs=1 count=1024 status=none
    fi
    chmod 400 "$dir/key/munge.key"
    munged --socket="$sock" --key-file="$dir/key/munge.key" \
           --pid-file="$dir/run/munged.pid" --log-file="$dir/log/munged.log" \
           --seed-file="$dir/key/munged.seed" --num-threads=2 --force \
        || die "munged failed to start"

    # --- slurm.conf ------------------------------------------------------------
    local node user cpus ctld_port slurmd_port
    node=$(hostname -s)
    user=$(id -un)
    cpus=${SHEAF_SLURM_CPUS:-$(nproc)}
    [[ $cpus =~ ^[1-9][0-9]*$ ]] || die "SHEAF_SLURM_CPUS must be a positive integer, not '$cpus'"
    ctld_port=$(free_port)
    slurmd_port=$((ctld_port + 1))
    cat >"$dir/slurm.conf" <<EOF
# Generated by $PROG for a local one-node test cluster.
ClusterName=sheaftest
SlurmctldHost=$node(127.0.0.1)
SlurmUser=$user
SlurmdUser=$user
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
# cred_expire also sets how long a requeued job waits before it may run again (default 120 s).
AuthInfo=socket=$sock,cred_expire=10
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
TmpFS=$dir/tmp
SlurmctldPidFile=$dir/run/slurmctld.pid
SlurmdPidFile=$dir/run/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
MailProg=/bin/true
# No cgroups in the container: plain /proc process tracking, no task binding.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
# No slurmdbd, so no sacct: completed jobs are logged one line each here instead.
JobCompType=jobcomp/filetxt
JobCompLoc=$dir/log/jobcomp.txt
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
# Keep latency low: no submit batching, full scheduling and backfill passes every
# second (slurmctld still only starts jobs about once a second).
SchedulerParameters=batch_sched_delay=0,sched_min_interval=0,sched_interval=1,bf_interval=1,default_queue_depth=1000
ReturnToService=2
SlurmdTimeout=60
MessageTimeout=10
KillWait=5
InactiveLimit=0
MinJobAge=600
MaxJobCount=100000
MaxArraySize=10001
# config_overrides: trust the CPU count below even if it exceeds the hardware, so
# that SHEAF_SLURM_CPUS can oversubscribe a small machine with many short tasks.
SlurmdParameters=config_overrides
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=debug Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF

    # --- daemons: both fork into the background and write their pid files ------
    export SLURM_CONF=$dir/slurm.conf
    slurmctld -f "$SLURM_CONF" || die "slurmctld failed to start"
    slurmd -f "$SLURM_CONF" -N "$node" || die "slurmd failed to start"

    # Wait until the node is idle (30 s); give up early if a daemon died.
    local d state=
    for _ in $(seq 150); do
        for d in slurmctld slurmd; do
            [[ -s $dir/run/$d.pid && -z $(live_pid "$dir" $d) ]] && die "$d exited"
        done
        state=$(sinfo -h -n "$node" -o %T 2>/dev/null || true)
        [[ $state == idle ]] && break
        sleep 0.2
    done
    [[ $state == idle ]] || die "node $node not idle after 30 s (state '${state:-none}')"

    trap - EXIT
    # Clients only need SLURM_CONF: the munge socket is taken from AuthInfo in slurm.conf.
    echo "export SLURM_CONF=$dir/slurm.conf"
}

case ${1:-} in
    available) cmd_available ;;
    start) [[ $# -eq 2 ]] || die "usage: $PROG start DIR"; cmd_start "$2" ;;
    stop)  [[ $# -eq 2 ]] || die "usage: $PROG stop DIR";  cmd_stop "$2" ;;
    *) echo "usage: $PROG available | start DIR | stop DIR" >&2; exit 2 ;;
esac
