#!/bin/bash
# The panel's scene file control driven with xdotool, for
# tests/window/panel_test.cpp (run inside xvfb-run): opens
# `frustum-demo window --scene START --effect plain --size 480x480 --panel`, then
#   a.png  as it starts
#   b.png  after choosing entry INDEX (0..7) of the "beside it" list
#   c.png  after typing MISSING into the path field and pressing Enter
#          (refused: the error on top of the panel, the view unchanged)
#   d.png  after P (the panel hidden)
# and quits with Esc. The widget positions are those of the panel's fixed
# layout (ImGui's default font and style) with the plain effect shown: the
# "scene file" section below the folded other effects; the list, longer
# than ImGui's eight rows, opens above its combo box.
# Usage: scene_clicks.sh FRUSTUM_DEMO OUT_DIR START INDEX MISSING
set -euo pipefail
demo=$1
out=$2
start=$3
index=$4
missing=$5
script=scene_clicks.sh
# shellcheck source=panel_steps.sh
source "$(dirname "$0")/panel_steps.sh"
open_window --scene "$start" --effect plain --size 480x480 --panel
settle
shot a.png
click 80 398 # the "beside it" list
click 80 $((253 + 17 * index)) # its entry INDEX
settle
shot b.png
click 150 375 # the path field: a click selects all of it
xdotool type --window "$wid" --delay 60 "$missing"
wait_frames 2
xdotool key --window "$wid" Return
settle
shot c.png
xdotool key --window "$wid" p
settle
shot d.png
finish
