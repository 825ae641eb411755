#!/usr/bin/env bash
# The viewer over time (issue 7): pv3d in a real window under Xvfb showing a simulated world
# (256 robots by default), sampling its resident memory and CPU every few seconds.
#
#   bash bench/viewer-soak.sh [SECONDS] [WORLD] [OUT.csv]      # defaults: 600, swarm, stdout summary
#
# Prints "t_s,rss_kib,cpu_s" rows to OUT.csv (if given) and a summary: RSS at the first and
# last sample after warm-up, its growth, mean CPU (cores) and frames drawn. The simulation
# runs in-process too, so the CPU is also split by thread: the simulation and its Player
# servers, the Player client threads, the UI thread, Mesa's rasteriser threads. Run it again
# with `--idle` as a fourth argument for a composition with no robots (the idle viewer).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
world=${2:-stage-worlds/swarm.world}
out=${3:-/dev/null}
mode=${4:-}
binary=${PV3D:-target/release/pv3d}   # PV3D=path: another build, to compare
[ -x "$binary" ] || cargo build --release -p pv3d

display=":$((90 + RANDOM % 300))"
Xvfb "$display" -screen 0 1280x900x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true' EXIT
sleep 1

if [ "$mode" = "--idle" ]; then
  composition=$(mktemp --suffix=.xml)
  printf '<pv3d><plugin library="libpv3d_lights"/><plugin library="libpv3d_ground"/><plugin library="libpv3d_grid"/></pv3d>\n' >"$composition"
  DISPLAY=$display "$binary" "$composition" --quit-after "$seconds" --frame-stats 2>/tmp/soak-stderr.$$ &
else
  DISPLAY=$display "$binary" --world "$world" --connect-timeout 20 --quit-after "$seconds" --frame-stats 2>/tmp/soak-stderr.$$ &
fi
pid=$!
ticks=$(getconf CLK_TCK)
# CPU ticks per kind of thread, one "kind ticks" line each.
thread_ticks() {
  for task in /proc/"$1"/task/*; do
    comm=$(cat "$task/comm" 2>/dev/null) || continue
    stat=$(cat "$task/stat" 2>/dev/null) || continue
    rest=${stat##*) }
    read -r -a f <<<"$rest"
    case "$comm" in
      player-sim* | player-server*) kind="simulation and its Player servers" ;;
      player\ *) kind="Player client threads" ;;
      llvmpipe*) kind="Mesa llvmpipe rasteriser threads" ;;
      pv3d) kind="UI thread: plugins, batch, egui, GL calls" ;;
      *) kind="other threads" ;;
    esac
    echo "$kind;$((f[11] + f[12]))"
  done | awk -F";" '{ t[$1] += $2 } END { for (k in t) print k ";" t[k] }'
}
threads_first=$(mktemp) threads_last=$(mktemp)
echo "t_s,rss_kib,cpu_s" >"$out"
start=$(date +%s.%N)
samples=()
while kill -0 "$pid" 2>/dev/null; do
  sleep 5
  [ -r "/proc/$pid/status" ] || break
  rss=$(awk '/^VmRSS/ {print $2}' "/proc/$pid/status" 2>/dev/null) || break
  cpu=$(awk -v t="$ticks" '{print ($14 + $15) / t}' "/proc/$pid/stat" 2>/dev/null) || break
  now=$(date +%s.%N)
  t=$(awk -v a="$now" -v b="$start" 'BEGIN { printf "%.1f", a - b }')
  echo "$t,$rss,$cpu" >>"$out"
  samples+=("$t,$rss,$cpu")
  # Thread times from the end of warm-up until shortly before pv3d quits and its threads end.
  if awk -v t="$t" -v end="$seconds" 'BEGIN { exit !(t >= 30 && t <= end - 6) }'; then
    if [ ! -s "$threads_first" ]; then
      { echo "t;$t"; thread_ticks "$pid"; } >"$threads_first"
    else
      { echo "t;$t"; thread_ticks "$pid"; } >"$threads_last"
    fi
  fi
done
wait "$pid" || true
frames=$(grep -o 'frames: .*' /tmp/soak-stderr.$$ || echo "frames: ?")
rm -f /tmp/soak-stderr.$$
# Warm-up: the first 30 s (connections, first scans, caches).
printf '%s\n' "${samples[@]}" | awk -F, -v frames="$frames" '
  $1 >= 30 { if (!first) { first = $2; t0 = $1; c0 = $3 } last = $2; t1 = $1; c1 = $3; n++ }
  END {
    if (n < 2) { print "too short: run at least 40 s"; exit 1 }
    printf "samples after warm-up: %d over %.0f s\n", n, t1 - t0
    printf "RSS: %d KiB at %.0f s, %d KiB at %.0f s (%+.1f%%)\n", first, t0, last, t1, 100 * (last - first) / first
    printf "CPU: %.3f cores (viewer and in-process simulation)\n", (c1 - c0) / (t1 - t0)
    printf "%s\n", frames
  }'
if [ -s "$threads_last" ]; then
  echo "CPU by thread (cores):"
  awk -F";" -v hz="$ticks" '
    NR == FNR { if ($1 == "t") t0 = $2; else a[$1] = $2; next }
    $1 == "t" { t1 = $2; next }
    { b[$1] = $2 }
    END { for (k in b) printf "  %.3f  %s\n", (b[k] - a[k]) / hz / (t1 - t0), k }' \
    "$threads_first" "$threads_last" | sort -rn
fi
rm -f "$threads_first" "$threads_last"
