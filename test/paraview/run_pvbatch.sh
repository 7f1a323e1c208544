#!/usr/bin/env bash
# Runs a ParaView Python script with pvbatch under a private virtual X server (Debian's
# ParaView needs a display to render; xvfb-run alone proved unreliable, and pvpython's
# rendering fails with GLXBadContext there).  Xvfb picks a free display itself and
# reports it once it is ready (-displayfd).  usage: run_pvbatch.sh script.py args...
set -euo pipefail
ready=$(mktemp)
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset 3>"$ready" >/dev/null 2>&1 &
xvfb=$!
# Wait for the server to go: a dying Xvfb removes its socket file, which would break a
# new server that has just taken the same display number.
trap 'kill $xvfb 2>/dev/null || true; wait $xvfb 2>/dev/null || true; rm -f "$ready"' EXIT
for _ in $(seq 200); do [ -s "$ready" ] && break; sleep 0.05; done
[ -s "$ready" ] || { echo "Xvfb did not start" >&2; exit 1; }
DISPLAY=":$(head -n1 "$ready")" pvbatch "$@"
