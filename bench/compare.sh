#!/usr/bin/env bash
# tribez side by side with its peers (bench/peers/), on the same inputs, in the same run.
#
#   bench/compare.sh [DEGREES]        # default "3 10 20"
#
# For each degree n, on the reference workload (bench/peers/workload.py):
#   * exact evaluation: tribez's fast kernel against gmpy2 integer homogeneous Horner (the
#     fastest exact peer), best of 5 on both sides, and a check that the values are identical;
#     with ALL_PEERS=1 also python-flint and Python fractions (same algorithm) and SymPy
#     (rational de Casteljau, on the first SYMPY_POINTS points);
#   * f64 evaluation: tribez's f64 Horner and de Casteljau against the compiled
#     Triangle.evaluate_barycentric_multi of the Python package `bezier`;
# then `tribez check` of CHECK_CLAIMS f64 results at n = 3, end to end, against reading, parsing
# and evaluating the same CSV in f64 on one thread; then whole-process exact evaluation:
# `tribez eval PATCH --points FILE --format json`, process start to exit, against gmpy2's integer
# homogeneous Horner timed in-process (Python's start, reading and printing excluded), on the
# issue's workloads PROCESS_CASES ("degree:points ..."), with the kernel alone on the same points
# beside it and the values compared as text: PROCESS_ROUNDS rounds, each timing gmpy2 (best of 3),
# the kernel (best of 3) and the whole process (PROCESS_RUNS runs) in turn; each figure is the
# best over all rounds.
#
# The peers are installed once into bench/.venv from the pinned bench/peers/requirements.txt
# (bench/venv.sh; needs python3 and PyPI). Environment: EXACT_POINTS (1000), FLOAT_POINTS
# (100000), CHECK_CLAIMS (1000000), CHECK_ROUNDS (3), ALL_PEERS (unset), SYMPY_POINTS (50), PROCESS_CASES
# ("3:4000 10:2000 20:500"), PROCESS_RUNS (3), PROCESS_ROUNDS (5), ONLY (unset; "process" or "check": that part alone).
# Timings move between runs on a shared machine: compare the ratios of one run, not absolutes.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
PEERS="$ROOT/bench/peers"
PY="$("$ROOT/bench/venv.sh")"
EXACT_POINTS="${EXACT_POINTS:-1000}"
FLOAT_POINTS="${FLOAT_POINTS:-100000}"
CHECK_CLAIMS="${CHECK_CLAIMS:-1000000}"
SYMPY_POINTS="${SYMPY_POINTS:-50}"
DEGREES="${1:-3 10 20}"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT

cargo build --release --bin tribez --example speed --manifest-path "$ROOT/Cargo.toml" >&2
TARGET="${CARGO_TARGET_DIR:-$ROOT/target}"
SPEED="$TARGET/release/examples/speed"
TRIBEZ="$TARGET/release/tribez"

field() { "$PY" -c "import json,sys; print(json.loads(sys.stdin.readline())['$1'])"; }
ratio() { echo "$1 / $2" | bc -l; }
peer() { (cd "$PEERS" && "$PY" "$@"); }

PROCESS_CASES="${PROCESS_CASES:-3:4000 10:2000 20:500}"
PROCESS_RUNS="${PROCESS_RUNS:-3}"
PROCESS_ROUNDS="${PROCESS_ROUNDS:-5}"
min() { if [ -z "$1" ]; then echo "$2"; else echo "if ($1 < $2) $1 else $2" | bc -l; fi; }
median() { printf '%s\n' "$@" | sort -g | awk '{v[NR]=$1} END {print (NR % 2) ? v[(NR+1)/2] : (v[NR/2] + v[NR/2+1]) / 2}'; }
ONLY="${ONLY:-}"
echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"

printf '%-4s %-40s %12s %12s %8s %s\n' n measure tribez_us peer_us ratio note
[ -n "$ONLY" ] && DEGREES=""
for n in $DEGREES; do
  case="$WORK/case_n$n.json"
  peer workload.py --degree "$n" --points "$EXACT_POINTS" --seed $((1000 + n)) > "$case"

  # exact: gmpy2 integer homogeneous Horner, and identical values
  peer exact.py "$case" --backend gmpy2 --algo horner > "$WORK/peer_values_$n.json"
  theirs=$(peer exact.py "$case" --backend gmpy2 --algo horner --time --repeat 5 | field us_per_point)
  line=$(SPEED_REPEAT=5 "$SPEED" exact "$case" --expect "$WORK/peer_values_$n.json")
  echo "$line" >&2
  ours=$(echo "$line" | field us_per_point)
  printf '%-4s %-40s %12.3f %12.3f %8.2f %s\n' "$n" "exact (gmpy2 homogeneous Horner)" "$ours" "$theirs" \
    "$(ratio "$theirs" "$ours")" "identical=$(echo "$line" | field identical_to_peer) mean_bits=$(echo "$line" | field mean_result_bits)"
  if [ -n "${ALL_PEERS:-}" ]; then
    for backend in flint fractions; do
      theirs=$(peer exact.py "$case" --backend "$backend" --algo horner --time --repeat 3 | field us_per_point)
      printf '%-4s %-40s %12.3f %12.3f %8.2f\n' "$n" "exact ($backend homogeneous Horner)" "$ours" "$theirs" "$(ratio "$theirs" "$ours")"
    done
    theirs=$(peer exact.py "$case" --backend sympy --algo casteljau --points "$SYMPY_POINTS" --time --repeat 1 | field us_per_point)
    printf '%-4s %-40s %12.3f %12.3f %8.2f\n' "$n" "exact (sympy rational de Casteljau)" "$ours" "$theirs" "$(ratio "$theirs" "$ours")"
  fi

  # f64: bezier's compiled evaluate_barycentric_multi against tribez's f64 paths
  theirs=$(peer bezier_float.py "$case" --time "$FLOAT_POINTS" | field us_per_point)
  "$SPEED" float "$case" "$FLOAT_POINTS" > "$WORK/float_$n.jsonl"
  cat "$WORK/float_$n.jsonl" >&2
  while read -r l; do
    what=$(echo "$l" | field what)
    ours=$(echo "$l" | field us_per_point)
    printf '%-4s %-40s %12.4f %12.4f %8.2f\n' "$n" "$what (bezier f64)" "$ours" "$theirs" "$(ratio "$theirs" "$ours")"
  done < "$WORK/float_$n.jsonl"
done

# whole-process exact evaluation against gmpy2 (and the kernel alone), the issue's workloads
if [ -z "$ONLY" ] || [ "$ONLY" = process ]; then
for spec in $PROCESS_CASES; do
  n="${spec%%:*}"; points="${spec##*:}"
  case="$WORK/process_n$n.json"
  peer workload.py --degree "$n" --points "$points" --seed $((1000 + n)) > "$case"
  peer to_tribez.py "$case" "$WORK/process_n$n.toml" "$WORK/process_n$n.csv"
  peer exact.py "$case" --backend gmpy2 --algo horner > "$WORK/process_peer_$n.json"
  # The three timings alternate over PROCESS_ROUNDS rounds and each keeps its best, so that all
  # three sample the same stretches of a machine whose speed drifts (the medians are over all
  # the whole-process runs).
  theirs=""; kernel=""; best=""; medians=""; cpus=""
  for _ in $(seq "$PROCESS_ROUNDS"); do
    t=$(peer exact.py "$case" --backend gmpy2 --algo horner --time --repeat 3 | field seconds)
    k=$(SPEED_REPEAT=3 SPEED_NO_CHECK=1 "$SPEED" exact "$case" | field seconds)
    whole=$(peer wall.py "$PROCESS_RUNS" "$WORK/process_out_$n.json" "$TRIBEZ" eval "$WORK/process_n$n.toml" \
      --points "$WORK/process_n$n.csv" --format json)
    theirs=$(min "$theirs" "$t"); kernel=$(min "$kernel" "$k"); best=$(min "$best" "$(echo "$whole" | field best)")
    medians="$medians $(echo "$whole" | field median)"; cpus="$cpus $(echo "$whole" | field cpu_median)"
  done
  median=$(median $medians)
  cpu=$(median $cpus)
  same=$("$PY" - "$WORK/process_out_$n.json" "$WORK/process_peer_$n.json" <<'PYEOF'
import json, sys
ours = [r["point"] for r in json.load(open(sys.argv[1]))["results"]]
theirs = json.load(open(sys.argv[2]))["results"]
print(ours == theirs)
PYEOF
)
  printf '%-4s %-40s %12.1f %12.1f %8.2f %s\n' "$n" "eval $points points, whole process (ms)" "$(echo "$best * 1000" | bc -l)" \
    "$(echo "$theirs * 1000" | bc -l)" "$(ratio "$theirs" "$best")" "identical=$same median=$(printf '%.1f' "$(echo "$median * 1000" | bc -l)") ms (ratio $(printf '%.2f' "$(ratio "$theirs" "$median")")), CPU $(printf '%.1f' "$(echo "$cpu * 1000" | bc -l)") ms"
  printf '%-4s %-40s %12.1f %12.1f %8.2f %s\n' "$n" "kernel alone, same $points points (ms)" "$(echo "$kernel * 1000" | bc -l)" \
    "$(echo "$theirs * 1000" | bc -l)" "$(ratio "$theirs" "$kernel")" "one thread"
done
fi
[ "$ONLY" = process ] && exit 0

# tribez check of CHECK_CLAIMS f64 results at n = 3, end to end, against the one-thread baseline
case3="$WORK/case_check_n3.json"
peer workload.py --degree 3 --points 0 --seed 1003 > "$case3"
"$PY" - "$case3" "$WORK/p3.toml" <<'PYEOF'
import json, sys
c = json.load(open(sys.argv[1])); n = c["degree"]
idx = [(n - j - k, j, k) for k in range(n + 1) for j in range(n - k + 1)]
rows = [f'"{i},{j},{k}" = [' + ", ".join(f'"{x}"' for x in p) + "]" for (i, j, k), p in zip(idx, c["nodes"])]
open(sys.argv[2], "w").write(f"degree = {n}\n[control_points]\n" + "\n".join(rows) + "\n")
PYEOF
"$SPEED" csv "$case3" "$CHECK_CLAIMS" "$WORK/claims3.csv" 2>/dev/null
# CHECK_ROUNDS rounds, each timing the baseline and then check; each keeps its least CPU time
# (the same rule as the other figures: the best of runs that sample the same stretches).
read_s=""; check_cpu=""; check_wall=""
for _ in $(seq "${CHECK_ROUNDS:-3}"); do
  /usr/bin/time -f "%e %U %S" -o "$WORK/time_base.txt" "$SPEED" read-eval "$case3" "$WORK/claims3.csv" --once > /dev/null
  read -r _ base_user base_sys < "$WORK/time_base.txt"
  read_s=$(min "$read_s" "$(echo "$base_user + $base_sys" | bc -l)")
  /usr/bin/time -f "%e %U %S" -o "$WORK/time.txt" "$TRIBEZ" check --patch "$WORK/p3.toml" --results "$WORK/claims3.csv" \
    --precision f64 --tolerance cond=9 > "$WORK/check.txt" || true
  read -r wall check_user check_sys < "$WORK/time.txt"
  cpu=$(echo "$check_user + $check_sys" | bc -l)
  if [ -z "$check_cpu" ] || [ "$(echo "$cpu < $check_cpu" | bc -l)" = 1 ]; then check_cpu=$cpu; check_wall=$wall; fi
done
printf '%-4s %-40s %12.3f %12.3f %8.1f %s\n' 3 "check $CHECK_CLAIMS f64 results, end to end (s)" "$check_cpu" "$read_s" \
  "$(ratio "$check_cpu" "$read_s")" "= check CPU time (wall $check_wall s) / CPU time of reading, parsing and f64 de Casteljau of the same CSV on one thread (one process); least of ${CHECK_ROUNDS:-3} alternating runs each"
grep -E "decided by the float filter" "$WORK/check.txt" >&2 || true
echo "ratio = peer time / tribez time (higher is better for tribez), except the check line: tribez / baseline (lower is better)"
