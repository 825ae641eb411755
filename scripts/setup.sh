#!/usr/bin/env bash
# Installs what building, running and testing pv3d needs on a fresh Debian machine.
# Rust (cargo, rustc 1.95) is expected to be there already; everything else comes from Debian.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  # xmllint validates configs/ against the Relax NG schema in the tests.
  libxml2-utils
  # Mesa's software OpenGL through EGL: screenshots and rendering tests with no X server.
  libegl1 libegl-mesa0 libgl1-mesa-dri
  # A real window with no display: Xvfb, plus what winit loads at run time.
  xvfb xauth libglx-mesa0 libx11-xcb1 libxcursor1 libxi6 libxkbcommon-x11-0
  # player-sim's speech device speaks what it is told into WAV files (tested).
  espeak-ng
  # Python for the player3 package and the Python-side tests (in a virtual environment).
  python3 python3-venv
  # The web page's tests drive a real browser (through Playwright, tests/web).
  chromium
  # Network namespaces for the tests of what discovers by multicast (DDS, Zenoh's scouting)
  # and of player-grade's sandbox: ip, unshare.
  iproute2 util-linux
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
command -v cargo >/dev/null || { echo "cargo not found: install Rust 1.95 first" >&2; exit 1; }

# Python's side (the player3 package and the tests that use Python readers) lives in .venv.
python3 -m venv .venv
.venv/bin/python -m pip install -q --upgrade pip
.venv/bin/python -m pip install -q -r scripts/python-requirements.txt
# player3, the Python package (python/), built from this checkout into .venv: release, since
# it is what students' programs and the benchmarks run.
VIRTUAL_ENV="$PWD/.venv" .venv/bin/maturin develop --release --quiet -m python/Cargo.toml
# player-grade, the class grader (docs/GRADING.md), beside the Python it runs programs with: an
# activated .venv has both on its PATH. Release, as player3 above (whose build it mostly shares).
cargo build --release --quiet -p player-grade
ln -sf "$PWD/target/release/player-grade" .venv/bin/player-grade
command -v npm >/dev/null || { echo "npm not found: install Node.js 20 or later first" >&2; exit 1; }
# The browser-side clients of the tests (tests/web): Playwright's driver (it drives Debian's
# Chromium; it downloads no browser of its own) and Foxglove's WebSocket client, pinned.
npm ci --prefix tests/web --no-audit --no-fund --loglevel=error
