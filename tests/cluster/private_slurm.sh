# A private single-node Slurm for a test, sourced by slurm_test.sh and slurm_run_test.sh:
# slurmctld + slurmd as root in a temporary folder $tmp, no munge (auth/none, cred/none),
# proctrack/pgid, task/none, their own ports on 127.0.0.1; SLURM_CONF exported. The daemons
# are stopped by their PIDs on every exit (trap). Exits 77 (skip) only when Slurm's daemons
# are not installed.
for tool in slurmctld slurmd sbatch squeue scontrol sinfo; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "SKIP: $tool not found: install Debian's slurm-wlm (the README's install line does)"
    exit 77
  fi
done

tmp=$(mktemp -d /tmp/chainbreak-slurm.XXXXXX)
stop_daemons() {
  local f pid
  for f in "$tmp/slurmd.pid" "$tmp/slurmctld.pid"; do
    [ -s "$f" ] || continue
    pid=$(cat "$f")
    kill "$pid" 2>/dev/null || continue
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
  done
  rm -rf "$tmp"
}
trap stop_daemons EXIT

free_port() {
  /usr/bin/python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}
host=$(hostname -s)
mkdir -p "$tmp/state" "$tmp/spool" "$tmp/out"
cat >"$tmp/slurm.conf" <<CONF
ClusterName=chainbreaktest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
AuthType=auth/none
CredType=cred/none
ProctrackType=proctrack/pgid
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
SlurmUser=root
SlurmdUser=root
MpiDefault=none
ReturnToService=2
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MaxArraySize=64
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$tmp/slurm.conf
slurmctld -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF"
for i in $(seq 100); do
  if sinfo --noheader -o %T 2>/dev/null | grep -qx idle; then break; fi
  if [ "$i" = 100 ]; then
    echo "FAIL: the node did not become idle in 20 s"; sinfo || true
    tail -20 "$tmp/slurmctld.log" "$tmp/slurmd.log" || true
    exit 1
  fi
  sleep 0.2
done
echo "slurm: node $host idle ($(nproc) CPUs), SLURM_CONF=$SLURM_CONF"

