#!/usr/bin/env bash
# A rustc wrapper (RUSTC_WRAPPER) for fuzz builds: the crates that rasterize and encode
# pictures are compiled without libFuzzer's coverage instrumentation; every other crate keeps
# it. Their code still runs on every input (a crash, panic or hang in them is still found),
# but their branches no longer steer the fuzzer: a formula label's anti-aliasing runs and
# deflate loops told libFuzzer nothing about our parsers, yet their coverage callbacks were
# half of valid_composition's time and filled its corpus with formulas at odd resolutions.
set -euo pipefail
rustc=$1
shift
crate=
prev=
for arg in "$@"; do
  [ "$prev" = --crate-name ] && crate=$arg
  prev=$arg
done
case $crate in
  tiny_skia | tiny_skia_path | png | fdeflate | flate2 | miniz_oxide | crc32fast | adler2 | simd_adler32 | image) ;;
  *) exec "$rustc" "$@" ;;
esac
args=()
for arg in "$@"; do
  case $arg in
    -Cpasses=sancov-module | -Cllvm-args=-sanitizer-coverage-*) ;;
    *) args+=("$arg") ;;
  esac
done
exec "$rustc" "${args[@]}"
