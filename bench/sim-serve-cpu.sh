#!/usr/bin/env bash
# player-sim serving swarm1024.world with every robot's laser (and, with --pose, position2d)
# subscribed by a Player client (issue 23): the server process's CPU over a window.
#
#   bash bench/sim-serve-cpu.sh [--pose] [PORT_BASE]        # defaults: laser only, 20000
#
# Starts `player-sim stage-worlds/swarm1024.world --port-base PORT_BASE`, then the
# subscribe_all example (1 024 clients in one process, 32 s); after the subscriptions and 4 s
# of settling, reads utime + stime of both processes from /proc over 20 s. Prints one line:
# server and client CPU (cores), the load average at both ends, and how far the slowest
# client's newest scan advanced (320 in 32 s is 10 Hz kept); then the server's CPU by thread.
# PLAYER_SIM=path and SUBSCRIBE_ALL=path compare other builds (run them back to back).
set -euo pipefail
cd "$(dirname "$0")/.."
pose=""
if [ "${1:-}" = "--pose" ]; then
  pose="--pose"
  shift
fi
port=${1:-20000}
server_bin=${PLAYER_SIM:-target/release/player-sim}
client_bin=${SUBSCRIBE_ALL:-target/release/examples/subscribe_all}
[ -x "$server_bin" ] || cargo build --release -p player-sim --bin player-sim
[ -x "$client_bin" ] || cargo build --release -p player-sim --example subscribe_all

log=$(mktemp -d "${TMPDIR:-/tmp}/sim-serve-cpu.XXXXXX")
"$server_bin" stage-worlds/swarm1024.world --port-base "$port" >"$log/server.out" 2>"$log/server.err" &
server=$!
# The server gone (and its ports free) before this returns: runs follow one another.
trap 'kill $server 2>/dev/null || true; wait $server 2>/dev/null || true; rm -rf "$log"' EXIT
for _ in $(seq 150); do grep -qs serving "$log/server.err" && break; sleep 0.2; done
kill -0 $server 2>/dev/null || { cat "$log/server.err" >&2; exit 1; }
"$client_bin" 1024 32 "$port" $pose >"$log/client.out" 2>&1 &
client=$!
for _ in $(seq 300); do grep -qs subscribed "$log/client.out" && break; sleep 0.2; done
sleep 4

tick=$(getconf CLK_TCK)
# utime + stime of a process or thread; the name in /proc/*/stat may hold spaces.
cpu() { sed 's/.*) //' "$1/stat" | awk '{print $12 + $13}'; }
threads() {
  for t in /proc/"$1"/task/*; do
    echo "$(tr ' ' _ <"$t/comm") $(cpu "$t")"
  done | awk '{sum[$1] += $2} END {for (k in sum) print k, sum[k]}' | sort
}
s0=$(cpu /proc/$server); c0=$(cpu /proc/$client); threads $server >"$log/t0"
t0=$(date +%s.%N); l0=$(cut -d' ' -f1 /proc/loadavg)
sleep 20
s1=$(cpu /proc/$server); c1=$(cpu /proc/$client); threads $server >"$log/t1"
t1=$(date +%s.%N); l1=$(cut -d' ' -f1 /proc/loadavg)
wait $client
span=$(echo "($t1 - $t0) * $tick" | bc -l)
printf "server %.3f cores  client %.3f cores  load %s-%s  %s\n" \
  "$(echo "($s1 - $s0) / $span" | bc -l)" "$(echo "($c1 - $c0) / $span" | bc -l)" \
  "$l0" "$l1" "$(tail -1 "$log/client.out")"
join "$log/t0" "$log/t1" | while read -r name a b; do
  printf "  %s %.3f\n" "$name" "$(echo "($b - $a) / $span" | bc -l)"
done
