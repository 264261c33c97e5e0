#!/bin/bash
# The window's control panel driven like a user would, with xdotool, for
# tests/window/panel_test.cpp (run inside xvfb-run): opens
# `frustum-demo window --size 480x360 --panel`, then
#   a.png  as it starts (plain effect, panel shown)
#   b.png  after choosing "lens" in the --effect list
#   c.png  after clicking the --lens-power slider a quarter along (about 0.5)
#   d.png  after clicking its left end (0: refused by the row, error in the panel)
# each with the window's state line beside it (a.state .. d.state: the
# effect and the lens power the window took), and quits with Esc. Widgets
# are clicked by name where the window says it drew them (click_widget).
# Usage: panel_clicks.sh FRUSTUM_DEMO OUT_DIR
set -euo pipefail
demo=$1
out=$2
script=panel_clicks.sh
# shellcheck source=panel_steps.sh
source "$(dirname "$0")/panel_steps.sh"
open_window --size 480x360 --panel
settle
shot a.png
click_widget --effect
click_widget --effect=lens
wait_state ' effect=lens '
settle
shot b.png
click_widget --lens-power 0.25 # (0, 2]: 0.5
wait_state ' lens-power=0[.]'
settle
shot c.png
click_widget --lens-power 0 # its left end: 0
settle
shot d.png
finish
