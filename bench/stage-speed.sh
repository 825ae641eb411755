#!/usr/bin/env bash
# stage-speed.sh - issue 34's speed comparison, in one run: real Stage 4.3 headless (the reference
# build, shared/tools/build-ref.sh, never in CI) against player-sim on the very same world file —
# 100 Pioneers with SICK lasers wandering in simple.world's cave for 60 simulated seconds, as fast
# as each can. Stage runs pinned to one core (`stage -g`, which quits at the world's quit_time);
# player-sim is `sim_speed`'s one-thread pass and its every-core pass. Rounds alternate the two so
# that a busy moment of the machine falls on both. Prints the times and the ratios, and after
# the rounds each side's median and the ratio of the medians (Stage's own time moves by half
# from hour to hour on a shared VM: quote many rounds, not one); only those numbers go into
# BENCHMARKS.md.
#
# Usage: bench/stage-speed.sh [ROUNDS]      (3 by default)
# Environment: REF_ROOT (/opt/ref), ROBOTS (100), SECONDS_SIM (60)
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
REPO=$(cd "$HERE/.." && pwd)
REF_ROOT=${REF_ROOT:-/opt/ref}
ROUNDS=${1:-3}
ROBOTS=${ROBOTS:-100}
SECONDS_SIM=${SECONDS_SIM:-60}
# shellcheck disable=SC1091
. "$REF_ROOT/tools/env.sh"

cd "$REPO"
cargo build --release -p bench --bin sim_speed >/dev/null 2>&1
SIM_SPEED=$REPO/target/release/sim_speed
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
world=$("$SIM_SPEED" --write-world "$tmp" --robots "$ROBOTS" --seconds "$SECONDS_SIM" \
  --stage-worlds "$REF_ROOT/src/stage/worlds")

now() { date +%s.%N; }
# The median of the numbers on standard input, one a line.
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
stages=() ones=() manys=()
echo "$ROBOTS wandering Pioneers with SICK lasers in Stage's cave, $SECONDS_SIM simulated s; $(nproc) cores"
for ((round = 1; round <= ROUNDS; round++)); do
  start=$(now)
  (cd "$tmp" && taskset -c 0 stage -g "$(basename "$world")" >"$tmp/stage.log" 2>&1)
  stage_s=$(echo "$(now) - $start" | bc -l)
  grep -q "Stage: done" "$tmp/stage.log" || { echo "Stage did not finish:"; tail -5 "$tmp/stage.log"; exit 1; }
  out=$("$SIM_SPEED" --robots "$ROBOTS" --seconds "$SECONDS_SIM" --swarm-seconds 0 \
    --stage-worlds "$REF_ROOT/src/stage/worlds")
  one=$(echo "$out" | sed -n 's/^one thread: *\([0-9.]*\) s wall.*/\1/p')
  many=$(echo "$out" | sed -n 's/^[0-9]* threads: *\([0-9.]*\) s wall.*/\1/p')
  printf 'round %d: Stage %.3f s, player-sim one thread %.3f s (%.1fx Stage), every core %.3f s (%.1fx Stage); load %s\n' \
    "$round" "$stage_s" "$one" "$(echo "$stage_s / $one" | bc -l)" "$many" \
    "$(echo "$stage_s / $many" | bc -l)" "$(cut -d' ' -f1-3 /proc/loadavg)"
  stages+=("$stage_s") ones+=("$one") manys+=("$many")
done
stage_m=$(printf '%s\n' "${stages[@]}" | median)
one_m=$(printf '%s\n' "${ones[@]}" | median)
many_m=$(printf '%s\n' "${manys[@]}" | median)
printf 'medians of %d rounds: Stage %.3f s, player-sim one thread %.3f s (%.1fx Stage), every core %.3f s (%.1fx Stage)\n' \
  "$ROUNDS" "$stage_m" "$one_m" "$(echo "$stage_m / $one_m" | bc -l)" "$many_m" \
  "$(echo "$stage_m / $many_m" | bc -l)"
