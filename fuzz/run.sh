#!/usr/bin/env bash
# Runs one fuzz target until it has executed RUNS inputs or SECONDS have passed, whichever is
# first, and prints one figures line for RESULTS.md: target, executions, seconds, executions
# a second, corpus size, and whether it crashed. New inputs go to target/corpus-work/TARGET
# (not committed); the committed seeds in corpus/TARGET, and the repository's own configs or
# worlds for the targets that read those, are read too.
#
#   bash fuzz/run.sh TARGET [RUNS] [SECONDS]      # defaults: 10 000 000 runs, 3 600 s
#
# SANITIZER=none: built without AddressSanitizer (in target/plain), and the crates that
# rasterize and encode pictures without coverage feedback (rustc-raster-uninstrumented.sh).
# For a target whose time goes to those crates (valid_composition: a formula label's
# typesetting) about ten times the inputs a second (170-290 under ASan, 3 600 here). Safe
# Rust gains little from ASan; what is lost is libFuzzer's -malloc_limit_mb (it needs ASan's
# allocator hooks) — one allocation over 2 GiB resident still ends the run through
# -rss_limit_mb.
# LANE=NAME: another run of the same target beside the first, on another core, sharing its
# corpus, with a log of its own (target/TARGET.NAME.log).
#
# Needs a nightly toolchain and cargo-fuzz (`cargo install cargo-fuzz`).
set -uo pipefail
cd "$(dirname "$0")"
target=$1
runs=${2:-10000000}
seconds=${3:-3600}
work=target/corpus-work/$target
mkdir -p "$work" "corpus/$target"
# Targets whose seeds are files the repository already has.
seeds=()
case $target in
  composition | valid_composition) seeds=(../configs) ;;
  stage_world) seeds=(../stage-worlds) ;;
  player_cfg) seeds=(../stage-worlds) ;;
esac
# Longest input tried. libFuzzer's default is the longest seed, and swarm1024.world is 90 KB:
# world files that long only repeat the model lines the shorter seeds already hold, and made
# each input several times slower to load.
max_len=()
case $target in
  stage_world | player_cfg) max_len=(-max_len=16384) ;;
esac
log=target/$target${LANE:+.$LANE}.log
build=()
if [ "${SANITIZER:-address}" = none ]; then
  build=(-s none --target-dir target/plain)
  export RUSTC_WRAPPER=$PWD/rustc-raster-uninstrumented.sh
fi
cargo +nightly fuzz run -O "${build[@]}" "$target" "$work" "corpus/$target" "${seeds[@]}" -- \
  -runs="$runs" -max_total_time="$seconds" -rss_limit_mb=2048 -malloc_limit_mb=1024 \
  -print_final_stats=1 "${max_len[@]}" >"$log" 2>&1
status=$?
executed=$(grep -a 'stat::number_of_executed_units' "$log" | awk '{print $2}')
time=$(grep -a -o 'Done [0-9]* runs in [0-9]* second' "$log" | awk '{print $5}')
# A run stopped by hand prints no "Done" line: its seconds from its average rate.
if [ -z "$time" ] && [ -n "$executed" ]; then
  rate=$(grep -a 'stat::average_exec_per_sec' "$log" | awk '{print $2}')
  [ "${rate:-0}" -gt 0 ] && time="about $(( executed / rate ))"
fi
corpus=$(find "$work" -type f | wc -l)
# Stopped by hand (SIGINT: libFuzzer exits 72, cargo fuzz 1) is not a crash: the log says so.
if [ "$status" -eq 0 ]; then
  verdict="no crash"
elif grep -aq 'libFuzzer: run interrupted' "$log" && ! grep -aq 'deadly signal\|panicked' "$log"; then
  verdict="no crash; stopped by hand"
else
  verdict="CRASH (exit $status, see fuzz/$log)"
fi
echo "$target | ${executed:-?} | ${time:-?} s | ${rate:-$(( ${executed:-0} / (${time:-0} > 0 ? ${time:-1} : 1) ))}/s | $corpus | $verdict"
exit $status
