#!/usr/bin/env bash
# The scaling table of docs/performance.md: exact evaluation cost and result size against the
# degree, on the reference workload of bench/peers/workload.py (dimension 3, control values p/q
# with |p| <= 2^16, 1 <= q <= 2^16, barycentric points with a common denominator <= 2^16),
# one core, best of 5.
#
#   bench/scaling.sh [DEGREES]        # default "3 10 20 30 50 100 200"
#
# Needs python3 (the workload generator uses only the standard library).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
PY="${PY:-python3}"
DEGREES="${1:-3 10 20 30 50 100 200}"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
cargo build --release --example speed --manifest-path "$ROOT/Cargo.toml" >&2
SPEED="${CARGO_TARGET_DIR:-$ROOT/target}/release/examples/speed"
field() { "$PY" -c "import json,sys; print(json.loads(sys.stdin.readline())['$1'])"; }
echo "| degree n | control points | exact µs/point (3 coordinates) | mean result size, bits (num + den) | per-patch preparation |"
echo "|---|---|---|---|---|"
for n in $DEGREES; do
  points=$(( n <= 20 ? 1000 : n <= 50 ? 100 : n <= 100 ? 20 : 5 ))
  case="$WORK/case_n$n.json"
  "$PY" "$ROOT/bench/peers/workload.py" --degree "$n" --points "$points" --seed $((2000 + n)) > "$case"
  line=$(SPEED_REPEAT=5 SPEED_NO_CHECK=1 "$SPEED" exact "$case")
  printf '| %s | %s | %s | %s | %s ms |\n' "$n" "$(( (n + 1) * (n + 2) / 2 ))" \
    "$(echo "$line" | field us_per_point | xargs printf '%.1f')" \
    "$(echo "$line" | field mean_result_bits | xargs printf '%.0f')" \
    "$(echo "$line" | field prepare_seconds | "$PY" -c 'import sys; print(f"{float(sys.stdin.read())*1000:.1f}")')"
done
