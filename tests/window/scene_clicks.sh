#!/bin/bash
# The panel's scene file control driven with xdotool, for
# tests/window/panel_test.cpp (run inside xvfb-run): opens
# `frustum-demo window --scene START --effect plain --size 480x480 --panel`, then
#   a.png  as it starts
#   b.png  after choosing the file ENTRY (a name) in the "beside it" list
#   c.png  after typing MISSING into the path field and pressing Enter
#          (refused: the error on top of the panel, the view unchanged)
#   d.png  after P (the panel hidden)
# and quits with Esc. Widgets are clicked by name where the window says it
# drew them (click_widget); ENTRY must be among the eight rows the open
# list shows.
# Usage: scene_clicks.sh FRUSTUM_DEMO OUT_DIR START ENTRY MISSING
set -euo pipefail
demo=$1
out=$2
start=$3
entry=$4
missing=$5
script=scene_clicks.sh
# shellcheck source=panel_steps.sh
source "$(dirname "$0")/panel_steps.sh"
open_window --scene "$start" --effect plain --size 480x480 --panel
settle
shot a.png
click_widget "beside it"
click_widget "beside it=$entry"
settle
shot b.png
click_widget "scene path" # a click selects all of it
xdotool type --window "$wid" --delay 60 "$missing"
wait_frames 2
xdotool key --window "$wid" Return
settle
shot c.png
xdotool key --window "$wid" p
settle
shot d.png
finish
