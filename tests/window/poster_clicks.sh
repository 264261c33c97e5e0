#!/bin/bash
# The panel's screenshot control driven with xdotool, for
# tests/window/poster_button_test.cpp (run inside xvfb-run): opens
# `frustum-demo window --size 640x400 --panel` in OUT_DIR, scrolls the
# panel to the "screenshot" button, sets "screenshot size" to 4x, then
#   window.png              the window's frame as the button is clicked
#   frustum-window-4x.png   what the button saved there (written whole)
# and quits with Esc. Widgets are clicked by name where the window says it
# drew them (click_widget).
# Usage: poster_clicks.sh FRUSTUM_DEMO OUT_DIR
set -euo pipefail
demo=$1
out=$2
script=poster_clicks.sh
# shellcheck source=panel_steps.sh
source "$(dirname "$0")/panel_steps.sh"
cd "$out"
open_window --size 640x400 --panel
show_widget screenshot
click_widget "screenshot size"
click_widget "screenshot size=4x"
# The list closes when an entry is taken.
poll_closed() { ! widget_rect "screenshot size=4x" >/dev/null; }
poll poll_closed || { echo "$script: the screenshot size list stayed open" >&2; exit 1; }
wait_frames 3
shot window.png
rm -f frustum-window-4x.png
click_widget screenshot
poster_saved() { [ -f frustum-window-4x.png ]; }
poll poster_saved || { echo "$script: no frustum-window-4x.png within ${wait_limit_s} s of the click" >&2; exit 1; }
finish
