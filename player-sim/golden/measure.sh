#!/usr/bin/env bash
# measure.sh - golden data for player-sim's tests, measured on a REFERENCE Player 3.1.1 + Stage 4.3
# (shared/tools/build-ref.sh builds it into $REF_ROOT, /opt/ref by default). Never run in CI.
#
# Usage:  player-sim/golden/measure.sh [WORLD...]
#   WORLD  a world file: Stage's stock ones by name (simple.world, from $REF_ROOT/src/stage/worlds),
#          ours by path (stage-worlds/blocks.world). Default: every stock world real Stage loads, and
#          our own stage-worlds that real Player + Stage run.
# Environment: REF_ROOT (/opt/ref), POSES (24 a world), SEED (34), PORT (a free one is chosen).
#
# For each world, in a scratch copy of its folder with every `ctrl` removed (robots stand still):
#   1. `golden pick` names the first robot with a ranger; `golden plan` draws POSES poses where it
#      stands clear (player-sim's reading of the world; the same poses are then asked of Stage).
#   2. A .cfg serving that robot's position2d and rangers and simulation:0 (usegui 0) is run by
#      real `player` under Xvfb; `golden read` places the robot at each pose through simulation:0
#      and records every ranger's ranges two steps later.
#   3. In Stage's simple.world and ours (`drives`), `golden drive` runs fixed drives from a fixed
#      pose and records the steps the odometry reported motion and the true end pose.
#   4. In golden/odometry.world (ours; `odometry`), `golden odom` records the pose position2d
#      reports step by step under fixed commands (localization "odom" with odom_error and
#      localization_origin, a diff and an omni robot), and `golden goto` the true pose of a
#      robot steered by a position command.
# What is kept: golden/stage/<world>.jsonl (a header line, then one line a pose; stock worlds under
# their names, ours as ours-<name>) and golden/stage/<world>-drives.jsonl. Only these numbers go into the repository, never
# Stage's worlds, bitmaps or code. Then the tests that compare player-sim with them are run
# (`cargo test -p player-sim --test golden -- --include-ignored`, the stock worlds from
# $REF_ROOT/src/stage/worlds).
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
REPO=$(cd "$HERE/../.." && pwd)
REF_ROOT=${REF_ROOT:-/opt/ref}
POSES=${POSES:-24}
SEED=${SEED:-34}
STOCK=$REF_ROOT/src/stage/worlds
OUT=$HERE/stage
# shellcheck disable=SC1091
. "$REF_ROOT/tools/env.sh"

# Stock worlds `stage -g` runs (fasr_plan needs a plugin; camera and everything need a display and
# are run here under Xvfb; wifi.world names a model type Stage does not have).
DEFAULT_STOCK="simple autolab camera everything SFU circuit fasr fasr2 large lsp_test mbicp
  pioneer_flocking pioneer_follow pioneer_walle roomba sensor_noise_demo sensor_noise_module_demo
  uoa_robotics_lab"
DEFAULT_OURS="simple classroom blocks oneport"

cd "$REPO"
cargo build --release -p player-sim --example golden >/dev/null
GOLDEN=$REPO/target/release/examples/golden
mkdir -p "$OUT"

tmp=$(mktemp -d)
disp=:$((150 + RANDOM % 100))
Xvfb "$disp" -screen 0 1024x768x24 -nolisten tcp >"$tmp/xvfb.log" 2>&1 &
xv=$!
pl=
trap 'for p in $pl $xv; do kill "$p" 2>/dev/null || true; done; rm -rf "$tmp"' EXIT
export DISPLAY=$disp

free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }

# start_player CFG PORT: real player on CFG, waits for it to listen
start_player() {
  (cd "$(dirname "$1")" && exec player -p "$2" "$(basename "$1")") >"$tmp/player.log" 2>&1 &
  pl=$!
  for _ in $(seq 1 120); do
    ss -ltnp | grep -q "127.0.0.1:$2 .*pid=$pl," && return 0
    kill -0 "$pl" 2>/dev/null || break
    sleep 0.25
  done
  echo "player did not listen on $2:"; tail -5 "$tmp/player.log"; return 1
}
stop_player() { kill "$pl" 2>/dev/null || true; wait "$pl" 2>/dev/null || true; pl=; }

# measure SOURCE_DIR WORLD_FILE NAME: golden readings of one world
measure() {
  local src=$1 file=$2 name=$3 dir=$tmp/w port robot rangers provides k
  rm -rf "$dir"; cp -r "$src" "$dir"
  for f in "$dir"/*.world "$dir"/*.inc; do
    [ -e "$f" ] && sed -E -i 's/ctrl[[:space:]]+"[^"]*"//' "$f"
  done
  read -r robot rangers < <("$GOLDEN" pick "$dir/$file")
  "$GOLDEN" plan "$dir/$file" "$robot" "$POSES" "$SEED" >"$dir/poses.txt"
  provides='"6665:position2d:0"'
  for ((k = 0; k < rangers; k++)); do provides="$provides \"6665:ranger:$k\""; done
  cat >"$dir/golden.cfg" <<EOF
driver ( name "stage" provides [ "6665:simulation:0" ] plugin "stageplugin" worldfile "$file" usegui 0 )
driver ( name "stage" provides [ $provides ] model "$robot" )
EOF
  port=$(free_port)
  sed -i "s/6665:/$port:/g" "$dir/golden.cfg"
  start_player "$dir/golden.cfg" "$port" || return 1
  {
    printf '{"world":"%s","robot":"%s","rangers":%s,"seed":%s,"stage":"%s"}\n' \
      "$name" "$robot" "$rangers" "$SEED" "$(cat "$REF_ROOT/BUILD-INFO" 2>/dev/null | grep -m1 -i stage | tr -d '"\n' || true)"
    "$GOLDEN" read "$port" "$robot" "$rangers" "$dir/poses.txt"
  } >"$tmp/out.jsonl"
  stop_player
  mv "$tmp/out.jsonl" "$OUT/$name.jsonl"
  echo "$name: $robot, $rangers ranger(s), $(($(wc -l <"$OUT/$name.jsonl") - 1)) poses"
}

# drives SOURCE_DIR WORLD_FILE ROBOT "X Y A" NAME: fixed drives from one pose, so many steps each
drives() {
  local src=$1 file=$2 robot=$3 start=$4 name=$5 dir=$tmp/w port
  rm -rf "$dir"; cp -r "$src" "$dir"
  for f in "$dir"/*.world "$dir"/*.inc; do
    [ -e "$f" ] && sed -E -i 's/ctrl[[:space:]]+"[^"]*"//' "$f"
  done
  port=$(free_port)
  cat >"$dir/golden.cfg" <<EOF
driver ( name "stage" provides [ "$port:simulation:0" ] plugin "stageplugin" worldfile "$file" usegui 0 )
driver ( name "stage" provides [ "$port:position2d:0" ] model "$robot" )
EOF
  start_player "$dir/golden.cfg" "$port" || return 1
  printf '{"world":"%s","robot":"%s"}\n' "$name" "$robot" >"$tmp/drives.jsonl"
  # forward m/s, turn rad/s, steps
  while read -r vx va steps; do
    "$GOLDEN" drive "$port" "$robot" "$start" "$vx" "$va" "$steps" >>"$tmp/drives.jsonl"
  done <<'EOF'
0.4 0 25
0.3 0.5 30
0 -1.0 20
0.5 0.3 20
0.2 -0.4 40
1.0 0 12
0 3.0 10
EOF
  stop_player
  mv "$tmp/drives.jsonl" "$OUT/$name-drives.jsonl"
  echo "$name drives: $(($(wc -l <"$OUT/$name-drives.jsonl") - 1))"
}

# odometry: Stage's reported odometry and its position control, in golden/odometry.world (ours)
odometry() {
  local dir=$tmp/w port
  rm -rf "$dir"; mkdir -p "$dir"; cp "$HERE/odometry.world" "$dir/"
  port=$(free_port)
  cat >"$dir/golden.cfg" <<EOF
driver ( name "stage" provides [ "$port:simulation:0" ] plugin "stageplugin" worldfile "odometry.world" usegui 0 )
driver ( name "stage" provides [ "$port:position2d:0" ] model "r0" )
driver ( name "stage" provides [ "$port:position2d:1" ] model "r1" )
driver ( name "stage" provides [ "$port:position2d:2" ] model "r2" )
EOF
  start_player "$dir/golden.cfg" "$port" || return 1
  {
    printf '{"world":"odometry"}\n'
    "$GOLDEN" odom "$port" 0 "0.4 0 0.3" 20
    "$GOLDEN" odom "$port" 0 "-0.3 0 -0.5" 20
    "$GOLDEN" odom "$port" 1 "0.2 0.3 0.2" 20
    "$GOLDEN" odom "$port" 1 "0 -0.4 0" 15
  } >"$tmp/odometry.jsonl"
  {
    printf '{"world":"odometry","robot":"r2"}\n'
    "$GOLDEN" goto "$port" r2 2 "1.5 -2 1.57" 80
    "$GOLDEN" goto "$port" r2 2 "-1 -3.5 -2" 80
  } >"$tmp/goto.jsonl"
  stop_player
  mv "$tmp/odometry.jsonl" "$OUT/ours-odometry-odom.jsonl"
  mv "$tmp/goto.jsonl" "$OUT/ours-odometry-goto.jsonl"
  echo "odometry: $(($(wc -l <"$OUT/ours-odometry-odom.jsonl") - 1)) drives, $(($(wc -l <"$OUT/ours-odometry-goto.jsonl") - 1)) goals"
}

all_drives() {
  drives "$STOCK" simple.world r0 "-6.946 -6.947 0.785" simple
  drives "$REPO/stage-worlds" simple.world r0 "-2 0 0" ours-simple
}

if [ $# -eq 0 ]; then
  for w in $DEFAULT_STOCK; do measure "$STOCK" "$w.world" "$w" || echo "$w: FAILED"; done
  for w in $DEFAULT_OURS; do measure "$REPO/stage-worlds" "$w.world" "ours-$w" || echo "ours-$w: FAILED"; done
  all_drives
  odometry
else
  for w in "$@"; do
    case "$w" in
      drives) all_drives ;;
      odometry) odometry ;;
      */*) measure "$REPO/$(dirname "$w")" "$(basename "$w")" "ours-$(basename "$w" .world)" ;;
      *) measure "$STOCK" "$w" "$(basename "$w" .world)" ;;
    esac
  done
fi

cd "$REPO"
STAGE_WORLDS=$STOCK cargo test -p player-sim --test golden -- --include-ignored --nocapture
