# shellcheck shell=bash
# A private single-node Slurm for tests: munged, slurmctld and slurmd as child processes of the calling shell,
# every file (configuration, munge key and socket, state, spool, logs, pid files) under one directory, nothing
# run through systemd and nothing written elsewhere. Source it from bash, then:
#
#   slurm_cluster_start DIR   # exports SLURM_CONF; status 77 with the daemons' log tails when Slurm cannot start
#   ...sbatch, squeue, scontrol, scancel as usual...
#   slurm_cluster_stop        # cancels what is left, waits for it, stops the daemons by PID
#
# Written for Debian's slurm-wlm 22.05 and munge 0.5.15; runs as root or as an ordinary user.

slurm_cluster_dir=
slurm_cluster_pids=()

# A TCP port nothing listens on now (the kernel's choice where python3 exists, else a random unused one).
slurm_free_port() {
    if command -v python3 >/dev/null 2>&1; then
        python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
        return
    fi
    local port
    while :; do
        port=$((20000 + RANDOM % 40000))
        ss -ltnH 2>/dev/null | awk '{print $4}' | grep -q ":$port\$" || { echo "$port"; return; }
    done
}

slurm_cluster_logs() {
    local daemon log
    for daemon in munged slurmctld slurmd; do
        # In the foreground each daemon also copies its log to stderr; stderr alone holds what came before the log.
        log=$slurm_cluster_dir/log/$daemon.log
        [ -s "$log" ] || log=$slurm_cluster_dir/log/$daemon.stderr
        [ -s "$log" ] || continue
        echo "--- last lines of $log"
        tail -n 15 "$log"
    done
}

# Starts the cluster under $1 (created if needed; it must not be shared). Status 0 when the node is idle,
# 77 (after the reason and the logs) when a binary is missing or a daemon does not come up.
slurm_cluster_start() {
    slurm_cluster_dir=$(realpath -m "$1")
    local tool
    for tool in munged slurmctld slurmd sbatch squeue sinfo scontrol scancel; do
        if ! command -v "$tool" >/dev/null 2>&1 && ! [ -x "/usr/sbin/$tool" ]; then
            echo "SKIP: $tool is not installed (apt-get install slurm-wlm munge; scripts/setup.sh does)"
            return 77
        fi
    done
    local d=$slurm_cluster_dir
    # munged wants no directory on the way to its key writable by others.
    mkdir -p "$d"/{munge,state,spool,log,run}
    chmod 755 "$d" "$d/munge"
    chmod 700 "$d/state" "$d/spool"
    head -c 1024 /dev/urandom >"$d/munge/munge.key"
    chmod 400 "$d/munge/munge.key"

    local munged=munged; command -v munged >/dev/null 2>&1 || munged=/usr/sbin/munged
    # --force: munged otherwise refuses a socket below a directory not everyone may enter (mktemp -d's 0700).
    "$munged" --foreground --force --socket="$d/munge/munge.socket" --key-file="$d/munge/munge.key" \
        --pid-file="$d/run/munged.pid" --log-file="$d/log/munged.log" --seed-file="$d/munge/munged.seed" \
        >"$d/log/munged.stderr" 2>&1 &
    slurm_cluster_pids+=($!)
    for _ in $(seq 50); do [ -S "$d/munge/munge.socket" ] && break; sleep 0.1; done
    if ! [ -S "$d/munge/munge.socket" ]; then
        echo "SKIP: munged did not start (no socket after 5 s)"
        slurm_cluster_logs; slurm_cluster_stop; return 77
    fi

    local node user ctld_port slurmd_port cpus
    node=$(hostname -s)
    user=$(id -un)
    ctld_port=$(slurm_free_port)
    slurmd_port=$(slurm_free_port)
    while [ "$slurmd_port" = "$ctld_port" ]; do slurmd_port=$(slurm_free_port); done
    cpus=$(nproc)
    cat >"$d/slurm.conf" <<EOF
ClusterName=trazotest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$d/munge/munge.socket
StateSaveLocation=$d/state
SlurmdSpoolDir=$d/spool/%n
SlurmctldPidFile=$d/run/slurmctld.pid
SlurmdPidFile=$d/run/slurmd.pid
SlurmctldLogFile=$d/log/slurmctld.log
SlurmdLogFile=$d/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
PlugStackConfig=$d/plugstack.conf
ProctrackType=proctrack/pgid
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
SchedulerParameters=sched_interval=1,bf_interval=1
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
MpiDefault=none
MailProg=/bin/true
ReturnToService=2
SlurmdParameters=config_overrides
KillWait=5
InactiveLimit=0
MinJobAge=600
SlurmctldTimeout=30
SlurmdTimeout=30
GresTypes=gpu
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus Gres=gpu:1 State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
    : >"$d/plugstack.conf"
    # One GPU without a device file: --gres=gpu:1 jobs are accepted and scheduled (what they run finds a GPU only
    # where the machine has one).
    echo "NodeName=$node Name=gpu File=/dev/null" >"$d/gres.conf"
    export SLURM_CONF=$d/slurm.conf

    local ctld=slurmctld slurmd=slurmd
    command -v slurmctld >/dev/null 2>&1 || ctld=/usr/sbin/slurmctld
    command -v slurmd >/dev/null 2>&1 || slurmd=/usr/sbin/slurmd
    # -i: ignore state files (there are none; a fresh cluster each time).
    "$ctld" -D -i -f "$SLURM_CONF" >"$d/log/slurmctld.stderr" 2>&1 &
    slurm_cluster_pids+=($!)
    "$slurmd" -D -N "$node" -f "$SLURM_CONF" >"$d/log/slurmd.stderr" 2>&1 &
    slurm_cluster_pids+=($!)

    local state=
    for _ in $(seq 150); do
        state=$(sinfo -h -n "$node" -o %t 2>/dev/null)
        [ "$state" = idle ] && return 0
        local pid
        for pid in "${slurm_cluster_pids[@]}"; do
            kill -0 "$pid" 2>/dev/null || { state="a daemon exited (pid $pid)"; break 2; }
        done
        sleep 0.2
    done
    echo "SKIP: the private Slurm did not come up (node state: ${state:-none} after 30 s)"
    slurm_cluster_logs
    slurm_cluster_stop
    return 77
}

# The slurmstepd processes of this cluster (they outlive slurmd by design): those whose open files lie in its
# directory (each keeps its step's socket and the spool open).
slurm_cluster_stepds() {
    local comm name pid
    for comm in /proc/[0-9]*/comm; do  # not pgrep: procps is not on every minimal machine
        read -r name 2>/dev/null <"$comm" && [ "$name" = slurmstepd ] || continue
        pid=${comm#/proc/}
        pid=${pid%/comm}
        # shellcheck disable=SC2010  # one ls for all the descriptors' targets
        ls -l "/proc/$pid/fd" 2>/dev/null | grep -q -- "-> $slurm_cluster_dir/" && echo "$pid"
    done
}

# Whether process $1 still runs (a child that exited stays a zombie until waited for; kill -0 finds it too).
slurm_running() {
    local state
    state=$(cut -d' ' -f3 "/proc/$1/stat" 2>/dev/null) && [ "$state" != Z ]
}

slurm_cluster_stop() {
    [ -n "$slurm_cluster_dir" ] || return 0
    if [ -n "${SLURM_CONF:-}" ] && [ "${#slurm_cluster_pids[@]}" -gt 1 ]; then
        scancel --user="$(id -un)" >/dev/null 2>&1
        for _ in $(seq 50); do
            [ -z "$(squeue -h -o %i 2>/dev/null)" ] && [ -z "$(slurm_cluster_stepds)" ] && break
            sleep 0.2
        done
    fi
    local pid
    for pid in $(slurm_cluster_stepds) "${slurm_cluster_pids[@]}"; do kill "$pid" 2>/dev/null; done
    for pid in "${slurm_cluster_pids[@]}"; do
        for _ in $(seq 50); do slurm_running "$pid" || break; sleep 0.1; done
        kill -KILL "$pid" 2>/dev/null
        wait "$pid" 2>/dev/null
    done
    slurm_cluster_pids=()
    slurm_cluster_dir=
}
