#!/bin/bash
# The window's control panel driven like a user would, with xdotool, for
# tests/window/panel_test.cpp (run inside xvfb-run): opens
# `frustum-demo window --size 480x360 --panel`, then
#   a.png  as it starts (plain effect, panel shown)
#   b.png  after choosing "lens" in the --effect list
#   c.png  after clicking the --lens-power slider a quarter along (about 0.5)
#   d.png  after clicking its left end (0: refused by the row, error in the panel)
# and quits with Esc. The widget positions are those of the panel's fixed
# layout (ImGui's default font and style, the panel at the window's left).
# Usage: panel_clicks.sh FRUSTUM_DEMO OUT_DIR
set -euo pipefail
demo=$1
out=$2
"$demo" window --size 480x360 --panel &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
wid=$(timeout 20 xdotool search --sync --onlyvisible --name '^frustum' | head -1)
# After each click the pointer leaves the panel (no tooltip over the view),
# then the window is read until two reads 0.3 s apart agree (nothing moves
# in the window once the click is drawn: the live numbers, which change every
# frame, lie below the 360 px window; a loaded machine only takes longer).
settle() {
  xdotool mousemove --window "$wid" 470 350
  local last="" now
  for _ in $(seq 40); do
    sleep 0.3
    now=$(xwd -id "$wid" -silent | md5sum)
    if [ "$now" = "$last" ]; then return 0; fi
    last=$now
  done
  echo "panel_clicks.sh: the window did not settle" >&2
  return 1
}
shot() { import -window "$wid" "$out/$1"; }
# A click as three steps with time between them, so that press and release
# land in different frames even on a loaded machine (ImGui 1.86 keeps only
# the button's state per frame: a press and release within one frame are
# lost, and a release it misses lets the slider follow the pointer away).
click() {
  xdotool mousemove --window "$wid" "$1" "$2"
  sleep 0.4
  xdotool mousedown 1
  sleep 0.4
  xdotool mouseup 1
  sleep 0.4
}
settle
shot a.png
click 100 76 # the --effect list (below --camera)
click 40 185 # its sixth entry: lens
settle
shot b.png
click 75 351 # --lens-power, a quarter along
settle
shot c.png
click 36 351 # its left end: 0
settle
shot d.png
xdotool key --window "$wid" Escape
wait $pid
trap - EXIT
