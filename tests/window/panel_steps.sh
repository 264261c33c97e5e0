# Steps shared by the xdotool scripts of the panel tests (panel_clicks.sh,
# scene_clicks.sh), sourced after they set $demo (frustum-demo), $out (the
# folder for screenshots) and $script (their name, for messages).
#
# They wait for the window's state, never for a fixed time: the window
# runs with FRUSTUM_WINDOW_STATE=$out/state, which it rewrites after every
# frame with "frame=N keys=K " and its settings (window::state_line()).
# Every wait gives up after $wait_limit_s (the run fails, saying what it
# waited for); a loaded machine only takes longer.
#
# open_window ARGS...: starts `frustum-demo window ARGS...` in the
# background ($pid, killed if the script fails), finds its window ($wid)
# and waits for its first frame;
# finish: Esc, and waits for the program to end.
wait_limit_s=${wait_limit_s:-120}
state_file=$out/state
open_window() {
  rm -f "$state_file" "$state_file.log" "$state_file.widgets"
  FRUSTUM_WINDOW_STATE=$state_file "$demo" window "$@" &
  pid=$!
  trap on_exit EXIT
  wid=$(timeout "$wait_limit_s" xdotool search --sync --onlyvisible --name '^frustum' | head -1)
  wait_state 'frame=[0-9]'
}
# on_exit: a script that fails stops the window and says how it ended: 143
# (SIGTERM) if it was still running, else its own status (a crash shows as
# 128 + the signal), so that a window that went away is not taken for a
# lost event.
on_exit() {
  local status=0
  kill "$pid" 2>/dev/null || true
  wait "$pid" || status=$?
  echo "$script: frustum-demo window ended with status $status" >&2
}
finish() {
  # The window may close on Esc's press before xdotool sends its release,
  # which then fails with X's BadWindow: that the press was taken is what
  # the wait below checks.
  xdotool key --window "$wid" Escape 2>/dev/null || true
  timeout "$wait_limit_s" tail --pid="$pid" -f /dev/null || { echo "$script: the window did not close" >&2; return 1; }
  wait "$pid"
  trap - EXIT
}
# poll CONDITION...: runs CONDITION until it succeeds, at most $wait_limit_s.
poll() {
  local deadline=$((SECONDS + wait_limit_s))
  until "$@"; do
    if [ "$SECONDS" -ge "$deadline" ]; then return 1; fi
    sleep 0.02
  done
}
state_matches() { grep -Eq -- "$1" "$state_file" 2>/dev/null; }
# wait_state REGEX: until the window's state line matches REGEX (e.g. ' effect=lens ').
wait_state() {
  poll state_matches "$1" || { echo "$script: the state never matched '$1': $(cat "$state_file" 2>/dev/null)" >&2; return 1; }
}
frame_now() { sed -n 's/^frame=\([0-9]*\) .*/\1/p' "$state_file" 2>/dev/null; }
frames_past() { local now; now=$(frame_now); [ -n "$now" ] && [ "$now" -ge "$1" ]; }
# wait_frames N: until the window has drawn N more frames (so that the
# events sent before were taken in a frame, and its outcome drawn).
wait_frames() {
  local target=$(($(frame_now) + $1))
  poll frames_past "$target" || { echo "$script: the window stopped drawing (frame $(frame_now), waited for $target)" >&2; return 1; }
}
#
# settle: the pointer leaves the panel (no tooltip over the view), frames
# are drawn after it, then the window is read until two reads with frames
# drawn between them agree (nothing moves in the window once a click is
# drawn: the live numbers that change every frame lie below the scripts'
# windows). A scene loaded in a frame is on screen in the frames after it.
settle() {
  xdotool mousemove --window "$wid" 470 350
  wait_frames 3
  local last="" now deadline=$((SECONDS + wait_limit_s))
  while [ "$SECONDS" -lt "$deadline" ]; do
    now=$(xwd -id "$wid" -silent | md5sum)
    if [ "$now" = "$last" ]; then return 0; fi
    last=$now
    wait_frames 2
  done
  echo "$script: the window did not settle" >&2
  return 1
}
# shot NAME.png: the screenshot, and the state line beside it (NAME.state).
shot() {
  import -window "$wid" "$out/$1"
  cp "$state_file" "$out/${1%.png}.state"
}
# widget_rect NAME: "x0 y0 x1 y1" of the panel's widget NAME as the last
# frame drew it (FRUSTUM_WINDOW_STATE's FILE.widgets: demo::PanelWidgets,
# whose names are the options, "LIST=ENTRY" and the labels); false while it
# is not drawn whole (a list's entry while it is closed, a widget scrolled
# out of the panel).
widget_rect() {
  awk -v name="$1" '{ n = $0; for (i = 0; i < 4; i++) sub(/^[^ ]+ /, "", n) }
                    n == name { print $1, $2, $3, $4; found = 1 } END { exit !found }' "$state_file.widgets" 2>/dev/null
}
widget_names() { cut -d' ' -f5- "$state_file.widgets" 2>/dev/null | paste -sd, -; }
# click_widget NAME [T]: a click T (0..1, default 0.5) along the widget
# NAME, at half its height, once it is drawn (a slider's rectangle is the
# span of its grab's centre: T = 0.25 is a quarter of its range).
click_widget() {
  local rect x y
  rect=$(poll widget_rect "$1") || { echo "$script: the panel never drew '$1' whole (it drew: $(widget_names))" >&2; return 1; }
  read -r x y < <(echo "$rect" | awk -v t="${2:-0.5}" '{ printf "%d %d\n", $1 + t * ($3 - $1) + 0.5, ($2 + $4) / 2 }')
  click "$x" "$y"
}
# show_widget NAME: the mouse wheel over the panel until NAME is drawn whole.
show_widget() {
  local steps=0
  until widget_rect "$1" >/dev/null; do
    if [ "$steps" -ge 60 ]; then echo "$script: '$1' not drawn after $steps wheel steps (drawn: $(widget_names))" >&2; return 1; fi
    xdotool mousemove --window "$wid" 160 200 click 5
    wait_frames 2
    steps=$((steps + 1))
  done
}
# A click as three steps with frames drawn between them, so that press and
# release land in different frames (ImGui 1.86 keeps only the button's
# state per frame: a press and release within one frame are lost, and a
# release it misses lets the slider follow the pointer away).
click() {
  xdotool mousemove --window "$wid" "$1" "$2"
  wait_frames 2
  xdotool mousedown 1
  wait_frames 2
  xdotool mouseup 1
  wait_frames 2
}
