#!/usr/bin/env bash
# tools/slurm-local.sh - a single-node Slurm on this machine, for `make farm-test` and for trying
# docs/regress.md's sbatch script before a real cluster.  Everything lives in one scratch folder.
#
#   tools/slurm-local.sh start DIR    write DIR/slurm.conf, start munged, slurmctld and slurmd,
#                                     wait until the node is idle; prints "export SLURM_CONF=..."
#   tools/slurm-local.sh stop DIR     stop the daemons it started (by their PID files, never by name)
#
# Needs root (the daemons run as root here: SlurmUser=root) and Debian's slurm-wlm and munge.
# munged is started as root with --force: on these machines /dev/null is not writable by the
# munge user, so the packaged way fails.
set -u
die() { echo "slurm-local: $*" >&2; exit 1; }
cmd=${1:-} dir=${2:-}
[ -n "$cmd" ] && [ -n "$dir" ] || die "usage: tools/slurm-local.sh start|stop DIR"
mkdir -p "$dir" || die "cannot create $dir"
dir=$(cd "$dir" && pwd)
conf=$dir/slurm.conf

stop_pid() {   # PIDFILE NAME
    [ -f "$1" ] || return 0
    local pid
    pid=$(cat "$1")
    if [ -n "$pid" ] && kill -0 "$pid" 2>/dev/null; then
        kill "$pid" 2>/dev/null
        for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
        kill -9 "$pid" 2>/dev/null
    fi
    rm -f "$1"
}

case $cmd in
start)
    [ "$(id -u)" = 0 ] || die "needs root (SlurmUser=root in this single-node setup)"
    for t in munged slurmctld slurmd sinfo; do command -v "$t" >/dev/null || die "$t not found (tools/install-deps.sh farm)"; done
    host=$(hostname -s)
    cpus=$(nproc)
    mem=$(awk '/^MemTotal:/ { printf "%d", $2 / 1024 * 0.9 }' /proc/meminfo)
    mkdir -p "$dir/state" "$dir/spool" "$dir/log" "$dir/munge"
    cat >"$conf" <<EOF
# single-node Slurm written by tools/slurm-local.sh
ClusterName=edgeflag
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
MinJobAge=60
NodeName=$host CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
    if ! munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then
        [ -f /etc/munge/munge.key ] || die "no /etc/munge/munge.key (reinstall munge)"
        # Without systemd nothing creates the socket folder (it is on a tmpfs).
        mkdir -p /run/munge /var/lib/munge /var/log/munge
        munged --force --pid-file="$dir/munge/munged.pid" >"$dir/log/munged.out" 2>&1 ||
            die "munged did not start: $(tail -n 1 "$dir/log/munged.out")"
        for _ in $(seq 30); do munge -n 2>/dev/null | unmunge >/dev/null 2>&1 && break; sleep 0.2; done
        munge -n | unmunge >/dev/null 2>&1 || die "munge does not answer"
        touch "$dir/munge/started-by-us"
    fi
    slurmctld -f "$conf" || die "slurmctld did not start (log: $dir/log/slurmctld.log)"
    slurmd -f "$conf" || die "slurmd did not start (log: $dir/log/slurmd.log)"
    for _ in $(seq 60); do
        state=$(SLURM_CONF=$conf sinfo -h -o %t 2>/dev/null | head -n 1)
        case $state in idle*|mix*|alloc*) break ;; esac
        sleep 0.5
    done
    [ "${state:-}" = idle ] || die "the node is '${state:-unknown}', not idle (logs in $dir/log)"
    echo "export SLURM_CONF=$conf"
    ;;
stop)
    stop_pid "$dir/slurmd.pid"
    stop_pid "$dir/slurmctld.pid"
    if [ -f "$dir/munge/started-by-us" ]; then
        if [ -f "$dir/munge/munged.pid" ]; then stop_pid "$dir/munge/munged.pid"; else munged --stop --force >/dev/null 2>&1; fi
        rm -f "$dir/munge/started-by-us"
    fi
    ;;
*) die "usage: tools/slurm-local.sh start|stop DIR" ;;
esac
