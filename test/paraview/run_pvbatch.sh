#!/usr/bin/env bash
# Runs a ParaView Python script with pvbatch under a private virtual X server (Debian's
# ParaView needs a display to render; xvfb-run alone proved unreliable, and pvpython's
# rendering fails with GLXBadContext there).  usage: run_pvbatch.sh script.py args...
set -euo pipefail
display=$(( 100 + RANDOM % 800 ))
Xvfb ":$display" -screen 0 1280x1024x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true' EXIT
for _ in $(seq 50); do [ -e "/tmp/.X11-unix/X$display" ] && break; sleep 0.1; done
DISPLAY=":$display" pvbatch "$@"
