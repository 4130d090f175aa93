#!/usr/bin/env bash
# Create (once) the virtual environment of the benchmark peers, bench/.venv, from the pinned
# bench/peers/requirements.txt, and print the path of its python. Reinstalls when the
# requirements file changes. Needs python3 with the venv module and access to PyPI.
#
#   PY="$(bench/venv.sh)"
set -euo pipefail
BENCH="$(cd "$(dirname "$0")" && pwd)"
VENV="${BENCH_VENV:-$BENCH/.venv}"
REQ="$BENCH/peers/requirements.txt"
if [ ! -x "$VENV/bin/python" ]; then
  python3 -m venv "$VENV" >&2
fi
stamp="$VENV/.requirements.sha256"
want="$(sha256sum "$REQ" | cut -d' ' -f1)"
if [ "$(cat "$stamp" 2>/dev/null || true)" != "$want" ]; then
  "$VENV/bin/python" -m pip install --quiet --upgrade pip >&2
  "$VENV/bin/python" -m pip install --quiet -r "$REQ" >&2
  echo "$want" > "$stamp"
fi
echo "$VENV/bin/python"
