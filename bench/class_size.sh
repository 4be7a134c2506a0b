#!/usr/bin/env bash
# How big a graded class is (issue 58): `aula grade` of a class of two vacuum submissions (the
# reference and the random bounce, each handed in as a student's MyAlgorithm.cpp) x SEEDS seeds
# of full 900 s runs (--Vacuum.Referee.Duration=900) on vacuum.world; prints the bytes per run of
# each kind of file in OUT/runs (the pages, pictures, compact traces, results, reports, logs),
# all kinds together, and the projection for 450 runs (30 students x 5 seeds x 3 worlds), against
# the budget of 50 MB per 450 runs. Nothing is timed.
# Usage: bench/class_size.sh BUILD_DIR [SEEDS=3] [EXTRA aula grade options...]
set -euo pipefail
build="$(cd "$1" && pwd)"; seeds="${2:-3}"; shift $(( $# < 2 ? $# : 2 ))
src="$(cd "$(dirname "$0")/.." && pwd)"
work="$(mktemp -d "${TMPDIR:-/tmp}/aula-class-size-XXXXXX")"
[ -n "${AULA_KEEP:-}" ] || trap 'rm -rf "$work"' EXIT

for who in reference bounce; do
  mkdir -p "$work/class/$who"
  cp "$src/components/vacuum/reference/roomba_steps.hpp" "$work/class/$who/"
  make=makeReferenceAlgorithm; [ "$who" = bounce ] && make=makeRandomBounceAlgorithm
  { cat "$src/components/vacuum/reference/RoombaReference.cpp"
    printf '\nnamespace aula::vacuum {\nstd::unique_ptr<VacuumAlgorithm> makeStudentAlgorithm(uint64_t seed) { return %s(seed); }\n}  // namespace aula::vacuum\n' "$make"
  } >"$work/class/$who/MyAlgorithm.cpp"
done

"$build/bin/aula" grade vacuum "$work"/class/* --seeds=1-"$seeds" --out="$work/out" --calibration-seeds=off \
  --Vacuum.Referee.Duration=900 "$@" >"$work/grade.txt" 2>&1 || { cat "$work/grade.txt"; exit 1; }

runs=$(find "$work/out/runs" -name '*.report.json' | wc -l)
[ "$runs" -gt 0 ] || { echo "no run graded"; cat "$work/grade.txt"; exit 1; }
# Every picture still a PNG whose chunks' CRCs hold (the grade rewrites it at zlib's best).
python3 - "$work/out/runs" <<'EOF2'
import pathlib, struct, sys, zlib
for png in pathlib.Path(sys.argv[1]).rglob('*.png'):
    d = png.read_bytes(); at = 8; idat = b''
    assert d[:8] == b'\x89PNG\r\n\x1a\n', png
    while at < len(d):
        n, = struct.unpack('>I', d[at:at + 4]); kind = d[at + 4:at + 8]
        assert zlib.crc32(d[at + 4:at + 8 + n]) == struct.unpack('>I', d[at + 8 + n:at + 12 + n])[0], (png, kind)
        if kind == b'IDAT': idat += d[at + 8:at + 8 + n]
        at += 12 + n
    zlib.decompress(idat)
EOF2
echo "$(date -u +%F): $runs full 900 s vacuum runs (reference and bounce, seeds 1-$seeds), aula grade $(git -C "$src" rev-parse --short HEAD 2>/dev/null || echo '?')"
printf '%-14s %8s %10s %12s\n' kind files 'bytes/run' 'per 450 runs'
total=0
for kind in .html .png .trace.z .trace.json .report.json .json .log; do
  case "$kind" in
    .json) files=$(find "$work/out/runs" -name '*.json' ! -name '*.report.json' ! -name '*.trace.json') ;;
    *) files=$(find "$work/out/runs" -name "*$kind") ;;
  esac
  n=$(printf '%s\n' "$files" | grep -c . || true)
  bytes=0; [ "$n" -gt 0 ] && bytes=$(printf '%s\n' "$files" | xargs stat -c %s | awk '{ s += $1 } END { print s }')
  total=$((total + bytes))
  printf '%-14s %8d %10d %9.1f MB\n' "$kind" "$n" "$((bytes / runs))" "$(echo "$bytes / $runs * 450 / 1000000" | bc -l)"
done
all=$(find "$work/out/runs" -type f -printf '%s\n' | awk '{ s += $1 } END { print s }')
printf '%-14s %8s %10d %9.1f MB (budget 50 MB: %s)\n' 'all files' '' "$((all / runs))" "$(echo "$all / $runs * 450 / 1000000" | bc -l)" \
  "$( [ $((all / runs * 450)) -le 50000000 ] && echo within || echo over)"
# The rest of the out folder (report.html, the builds' sources and logs, the manifest) grows with
# the students: 30 of them for 450 runs.
other=$(du -sb --exclude=runs "$work/out" | cut -f1)
printf '%-14s %8s %10d %9.1f MB (the out folder beside runs/: %d bytes for 2 students, 30 in 450 runs)\n' 'the rest' '' \
  "$((other / runs))" "$(echo "$other / 2 * 30 / 1000000" | bc -l)" "$other"
whole=$(echo "($all / $runs * 450 + $other / 2 * 30) / 1000000" | bc -l)
printf '%-14s %8s %10s %9.1f MB (budget 50 MB: %s)\n' 'the out folder' '' '' "$whole" "$(echo "$whole <= 50" | bc -l | sed 's/1/within/;s/0/over/')"
