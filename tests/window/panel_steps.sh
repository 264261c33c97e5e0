# Steps shared by the xdotool scripts of the panel tests (panel_clicks.sh,
# scene_clicks.sh), sourced after they set $demo (frustum-demo), $out (the
# folder for screenshots) and $script (their name, for messages).
#
# open_window ARGS...: starts `frustum-demo window ARGS...` in the
# background ($pid, killed if the script fails) and finds its window ($wid);
# finish: Esc, and waits for the program to end.
open_window() {
  "$demo" window "$@" &
  pid=$!
  trap 'kill $pid 2>/dev/null || true' EXIT
  wid=$(timeout 20 xdotool search --sync --onlyvisible --name '^frustum' | head -1)
}
finish() {
  xdotool key --window "$wid" Escape
  wait "$pid"
  trap - EXIT
}
#
# settle: the pointer leaves the panel (no tooltip over the view), then the
# window is read until two reads 0.3 s apart agree (nothing moves in the
# window once a click is drawn: the live numbers that change every frame lie
# below the scripts' windows; a loaded machine only takes longer).
settle() {
  xdotool mousemove --window "$wid" 470 350
  local last="" now
  for _ in $(seq 40); do
    sleep 0.3
    now=$(xwd -id "$wid" -silent | md5sum)
    if [ "$now" = "$last" ]; then return 0; fi
    last=$now
  done
  echo "$script: the window did not settle" >&2
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
