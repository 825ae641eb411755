#!/usr/bin/env bash
# The README's test command: every test of the project — Rust, then Python (pytest, in the
# virtual environment scripts/setup.sh made) — and the first failure fails the run.
set -euo pipefail
cd "$(dirname "$0")/.."

cargo test --workspace

python_suites=()
for dir in python/tests tests/python; do
  [ -d "$dir" ] && python_suites+=("$dir")
done
if [ "${#python_suites[@]}" -gt 0 ]; then
  [ -x .venv/bin/python ] || { echo "no .venv: run scripts/setup.sh first" >&2; exit 1; }
  .venv/bin/python -m pytest -q "${python_suites[@]}"
fi
