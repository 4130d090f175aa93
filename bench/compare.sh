#!/usr/bin/env bash
# Run tribez and the peers of ../shared/peers on the same inputs in the same run; print ratios.
#
#   bench/compare.sh [DEGREES]        # default "3 10 20"
#
# Needs the peers' venv: python3 -m venv /tmp/peers-venv &&
#   /tmp/peers-venv/bin/pip install bezier sympy python-flint gmpy2 numpy
# Environment: PEERS (default ../shared/peers from the repo root), PY (default
# /tmp/peers-venv/bin/python), EXACT_POINTS (1000), FLOAT_POINTS (100000).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
PEERS="${PEERS:-$ROOT/../shared/peers}"
PY="${PY:-/tmp/peers-venv/bin/python}"
EXACT_POINTS="${EXACT_POINTS:-1000}"
FLOAT_POINTS="${FLOAT_POINTS:-100000}"
DEGREES="${1:-3 10 20}"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT

cargo build --release --bin tribez --example speed --manifest-path "$ROOT/Cargo.toml" >&2
TARGET="${CARGO_TARGET_DIR:-$ROOT/target}"
SPEED="$TARGET/release/examples/speed"

field() { "$PY" -c "import json,sys; print(json.loads(sys.stdin.readline())['$1'])"; }
# Timings are best of 5 (exact) on both sides; on a loaded machine rerun and compare ratios, not absolutes.

printf '%-4s %-34s %12s %12s %8s %s\n' n measure tribez_us peer_us ratio note
for n in $DEGREES; do
  case="$WORK/case_n$n.json"
  (cd "$PEERS" && "$PY" -c "import json,common; json.dump(common.random_case($n, 3, $EXACT_POINTS, seed=1000 + $n), open('$case', 'w'))")
  # exact: gmpy2 integer homogeneous Horner vs tribez, and identical results
  (cd "$PEERS" && "$PY" exact_eval.py "$case" --backend gmpy2 --algo homog_horner) > "$WORK/peer_values_$n.json"
  # best of 5 on both sides (a run of 1000 points at n = 3 takes milliseconds: noisy)
  peer=$(for r in 1 2 3 4 5; do (cd "$PEERS" && "$PY" exact_eval.py --time "$case" --backend gmpy2 --algo homog_horner | field us_per_point); done | sort -g | head -1)
  line=$(SPEED_REPEAT=5 "$SPEED" exact "$case" --expect "$WORK/peer_values_$n.json")
  ours=$(echo "$line" | field us_per_point)
  same=$(echo "$line" | field identical_to_peer)
  bits=$(echo "$line" | field mean_result_bits)
  printf '%-4s %-34s %12.3f %12.3f %8.2f %s\n' "$n" "exact (gmpy2 homog_horner)" "$ours" "$peer" "$(echo "$peer / $ours" | bc -l)" "identical=$same mean_bits=$bits"
  echo "$line" >&2
  # float: bezier's compiled evaluate_barycentric_multi vs tribez f64 Horner
  peer=$(cd "$PEERS" && "$PY" peer_eval.py --time "$FLOAT_POINTS" "$case" | field us_per_point)
  "$SPEED" float "$case" "$FLOAT_POINTS" > "$WORK/float_$n.jsonl"
  cat "$WORK/float_$n.jsonl" >&2
  while read -r l; do
    what=$(echo "$l" | field what)
    ours=$(echo "$l" | field us_per_point)
    printf '%-4s %-34s %12.4f %12.4f %8.2f\n' "$n" "$what (bezier f64)" "$ours" "$peer" "$(echo "$peer / $ours" | bc -l)"
  done < "$WORK/float_$n.jsonl"
done
# check of CHECK_CLAIMS f64 claims at n = 3 against plain f64 evaluation of the same points
CHECK_CLAIMS="${CHECK_CLAIMS:-1000000}"
case3="$WORK/case_check_n3.json"
(cd "$PEERS" && "$PY" -c "import json,common; json.dump(common.random_case(3, 3, 0, seed=1003), open('$case3', 'w'))")
"$PY" - "$case3" "$WORK/p3.toml" <<'PYEOF'
import json, sys
c = json.load(open(sys.argv[1])); n = c["degree"]
idx = [(n - j - k, j, k) for k in range(n + 1) for j in range(n - k + 1)]
rows = [f'"{i},{j},{k}" = [' + ", ".join(f'"{x}"' for x in p) + "]" for (i, j, k), p in zip(idx, c["nodes"])]
open(sys.argv[2], "w").write(f"degree = {n}\n[control_points]\n" + "\n".join(rows) + "\n")
PYEOF
"$SPEED" csv "$case3" "$CHECK_CLAIMS" "$WORK/claims3.csv" 2>/dev/null
read_s=$("$SPEED" read-eval "$case3" "$WORK/claims3.csv" | field seconds)
# tribez check on both cores: compare its CPU time (user + system) with the one-thread baseline
/usr/bin/time -f "%e %U %S" -o "$WORK/time.txt" "$TARGET/release/tribez" check --patch "$WORK/p3.toml" --results "$WORK/claims3.csv" --precision f64 --tolerance cond=9 > "$WORK/check.txt" || true
read -r check_wall check_user check_sys < "$WORK/time.txt"
check_cpu=$(echo "$check_user + $check_sys" | bc -l)
printf '%-4s %-34s %12.3f %12.3f %8.1f %s\n' 3 "check $CHECK_CLAIMS f64 claims, end to end (s)" "$check_cpu" "$read_s" "$(echo "$check_cpu / $read_s" | bc -l)" "= check CPU time (wall $check_wall s on 2 cores) / reading, parsing and f64 de Casteljau of the same CSV on one thread"
grep -E "decided by the float filter" "$WORK/check.txt" >&2 || true
echo "ratio = peer time / tribez time (higher is better for tribez); targets: exact >= 5, f64 Horner >= 2;"
echo "the check line is tribez / baseline (lower is better); the 10x target for check is measured in memory by cargo bench --bench check"
