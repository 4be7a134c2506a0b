#!/usr/bin/env bash
# `aula grade --engine=slurm` on a real single-node Slurm cluster that this test starts itself
# (munged, slurmctld and slurmd as root, everything in a temp folder, its own ports), against
# the local engine on the same class: the two grades.csv must be identical.
# Usage: test_grade_slurm.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src="$1"; build="$2"
work="$(mktemp -d "${TMPDIR:-/tmp}/aula-slurm-XXXXXX")"
chmod 755 "$work"
stop_cluster() {
  # By the pids the daemons wrote, never by name: a real cluster on this machine is not ours.
  for pid_file in "$work/slurmd.pid" "$work/slurmctld.pid" "$work/munge/munged.pid"; do
    [ -s "$pid_file" ] && kill "$(cat "$pid_file")" 2>/dev/null || true
  done
  sleep 0.5
  rm -rf "$work"
}
trap stop_cluster EXIT
fail() {
  echo "FAIL: $*"
  for log in slurmctld.log slurmd.log; do echo "--- $log"; tail -20 "$work/$log" 2>/dev/null || true; done
  exit 1
}

for tool in munged slurmctld slurmd sbatch sinfo; do
  command -v "$tool" >/dev/null || [ -x "/usr/sbin/$tool" ] || fail "$tool is not installed (scripts/install-deps.sh installs Slurm and munge)"
done
[ -r /etc/munge/munge.key ] || fail "/etc/munge/munge.key is missing (the munge package creates it)"

# munge, on a socket of its own.
mkdir -p "$work/munge" "$work/state" "$work/spool"
chmod 700 "$work/munge"
/usr/sbin/munged --force --socket="$work/munge/munge.socket" --pid-file="$work/munge/munged.pid" \
  --log-file="$work/munge/munged.log" --seed-file="$work/munge/munged.seed" --key-file=/etc/munge/munge.key \
  || fail "munged did not start"

host="$(hostname -s)"
# Slurm's daemons and commands find the controller and the node by this name: where it does not
# resolve, each of them retries for seconds and the cluster never comes up (the test would only
# time out), so say it at once.
getent hosts "$host" >/dev/null ||
  fail "this machine's name '$host' does not resolve (not in /etc/hosts nor DNS): Slurm's daemons find each other by it"
cat >"$work/slurm.conf" <<CONF
ClusterName=aulatest
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$work/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
SlurmctldPort=16817
SlurmdPort=16818
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$work/slurm.conf"
/usr/sbin/slurmctld || fail "slurmctld did not start"
/usr/sbin/slurmd || fail "slurmd did not start"
for _ in $(seq 1 60); do
  sinfo -h -o %T 2>/dev/null | grep -q idle && break
  sleep 0.5
done
sinfo -h -o %T | grep -q idle || fail "the node never became idle"

# The class: the reference as a plugin, one that does nothing, one that does not compile, one
# that throws.
subs="$work/submissions"
mkdir -p "$subs/good" "$subs/lazy" "$subs/broken" "$subs/thrower"
cp "$src/components/vacuum/reference/roomba_steps.hpp" "$subs/good/"  # the reference's steps, beside it
{ cat "$src/components/vacuum/reference/RoombaReference.cpp"
  printf '\nnamespace aula::vacuum {\nstd::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t seed) { return makeReferenceAlgorithm(seed); }\n}  // namespace aula::vacuum\n'
} >"$subs/good/MyAlgorithm.cpp"
cp "$src/tests/data/plugins/does_nothing.cpp" "$subs/lazy/MyAlgorithm.cpp"
cp "$src/tests/data/plugins/throws.cpp" "$subs/thrower/MyAlgorithm.cpp"
printf '#include <aula/vacuum/vacuum_algorithm.hpp>\nint broken( { return 0; }\n' >"$subs/broken/MyAlgorithm.cpp"

grade() {  # grade ENGINE OUT
  "$build/bin/aula" grade vacuum "$subs/good" "$subs/lazy" "$subs/broken" "$subs/thrower" --seeds=1-2 --jobs=2 \
    --out="$2" --engine="$1" --Vacuum.Referee.Duration=60 --calibration-seeds=off >"$2.txt" 2>&1 || { cat "$2.txt"; fail "aula grade --engine=$1 failed"; }
}
grade slurm "$work/slurm-out"
grade local "$work/local-out"
ls "$work/slurm-out/slurm/"task-*.out >/dev/null 2>&1 || fail "no Slurm task wrote its output: the runs did not go through Slurm"
[ "$(ls "$work/slurm-out/runs"/*/*.json | grep -vc "report\|trace")" = 8 ] || fail "the Slurm tasks did not write 8 results"
if ! diff "$work/local-out/grades.csv" "$work/slurm-out/grades.csv"; then
  fail "grades.csv differs between the local engine and Slurm"
fi
grep -q '^good,' "$work/slurm-out/grades.csv" || fail "no row for the good submission"
echo "slurm: $(grep -c . "$work/slurm-out/grades.csv") lines of grades.csv identical to the local engine's"
cat "$work/slurm-out/grades.csv"
