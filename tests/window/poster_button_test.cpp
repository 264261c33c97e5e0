// The panel's screenshot control at a multiple of the window (issue 36),
// driven like a user would under xvfb-run with xdotool: the "screenshot
// size" list set to 4x, then the "screenshot" button. The file it saves,
// frustum-window-4x.png, must be 4 x the window's size, and box-filtered 4x
// it must be the window's own frame beside the panel (the poster draws the
// same view as crop tiles, without the panel).
//
// The script below finds the widgets by their colours in a screenshot
// (ImGui's dark style: a button's fill is the bluest thing in the panel, a
// frame's darker), so it does not depend on how many rows the panel has
// above them; every wait is for a state (the window's pixels settled or
// changed, the file there with a stable size) with a timeout, never a
// fixed sleep.
#include "process.hpp"
#include "shots.hpp"

#include "../skips.hpp"

#include <doctest/doctest.h>

#include <demo/window_panel.hpp>
#include <image/compare.hpp>
#include <image/thumbnail.hpp>

#include <fstream>
#include <string>
#include <vector>

namespace {

using support::TempDir;

constexpr int kWindowWidthPx = 640;
constexpr int kWindowHeightPx = 400;
constexpr int kScale = 4;
constexpr int kPanelPx = static_cast<int>(demo::kPanelWidthPx) + 1; // with its border

// Run as: bash poster_button.sh FRUSTUM_DEMO OUT_DIR (inside xvfb-run).
// Writes OUT_DIR/window.png (the window's frame as the button is clicked)
// and, from the window, OUT_DIR/frustum-window-4x.png. A step that times
// out exits non-zero with a line saying which.
constexpr const char* kScript = R"script(#!/bin/bash
set -euo pipefail
demo=$1
out=$2
cd "$out"
fail() { echo "poster_button.sh: $*" >&2; exit 1; }
"$demo" window --size 640x400 --panel &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
wid=$(timeout 30 xdotool search --sync --onlyvisible --name '^frustum' | head -1)
[ -n "$wid" ] || fail "no window within 30 s"

# md5 of the window's pixels in a rectangle (W H X Y).
region() { import -window "$wid" -crop "$1x$2+$3+$4" +repage rgb:- 2>/dev/null | md5sum; }
# Waits until the rectangle reads the same twice 0.2 s apart (at most 30 s).
settled() {
  local last="" now
  for _ in $(seq 150); do
    now=$(region "$@")
    if [ "$now" = "$last" ]; then return 0; fi
    last=$now
    sleep 0.2
  done
  fail "the window's $1x$2+$3+$4 did not settle"
}
# Waits until the rectangle differs from md5 $1 (at most $2 s); false if it did not.
changed_from() {
  local before=$1 limit=$2; shift 2
  for _ in $(seq $((limit * 5))); do
    if [ "$(region "$@")" != "$before" ]; then return 0; fi
    sleep 0.2
  done
  return 1
}
# A click at X Y that must change the rectangle W H X0 Y0: pressed, then
# released once the press was drawn (a button or a row shows its pressed
# colour) or after 2 s (a list shows none), and again with a longer hold
# (ImGui 1.86 drops a press and release within one frame) until it does.
click_until_changed() {
  local x=$1 y=$2; shift 2
  xdotool mousemove --window "$wid" "$x" "$y"
  settled "$@"
  local before
  before=$(region "$@")
  for try in 1 2 3 4 5; do
    xdotool mousedown 1
    changed_from "$before" 2 "$@" || true
    sleep "0.$try"
    xdotool mouseup 1
    if changed_from "$before" 10 "$@"; then settled "$@"; return 0; fi
  done
  fail "a click at $x,$y changed nothing in $3x$4+$5+$6"
}
# Per row of column X of a screenshot 400 px high: "y class", the class
# of ImGui's dark style colour there: button (the bluest fill), frame (a
# list, a slider), header (a collapsing header, a list's chosen row), else -.
classes() {
  convert "$1" -crop "1x400+$2+0" +repage -depth 8 txt:- | awk -F'[ ,:()]+' '
    NR > 1 {
      g = $4; b = $5; c = "-";
      if (b >= 105 && b <= 135 && g >= 65 && g <= 90) c = "button";
      else if (b >= 70 && b <= 86 && g >= 45 && g <= 60) c = "frame";
      else if (b >= 86 && b <= 100 && g >= 58 && g <= 70) c = "header";
      print $2, c
    }'
}
# The runs of rows, bottom to top as "top bottom" lines, where column X of
# the screenshot has class WANT and (with a fourth argument) column NOT_X
# has not.
runs() {
  classes "$1" "$2" >classes-a.txt
  if [ $# -ge 4 ]; then classes "$1" "$4" >classes-b.txt; else : >classes-b.txt; fi
  awk -v want="$3" '
    FILENAME == ARGV[1] { not[$1] = $2; next }
    { hit = ($2 == want && not[$1] != want) }
    hit && start < 0 { start = $1 }
    !hit && start >= 0 { print start, $1 - 1; start = -1 }
    BEGIN { start = -1 }
    END { if (start >= 0) print start, 399 }' classes-b.txt classes-a.txt | tac
}

# The panel scrolled to its end: the screenshot rows are its last.
settled 310 400 330 0
xdotool mousemove --window "$wid" 160 200
xdotool click --repeat 40 --delay 30 5
settled 330 120 0 280
import -window "$wid" scrolled.png
# The lowest button is "screenshot"; the frame right above it the size list.
read -r button_top button_bottom < <(runs scrolled.png 12 button | head -1) || fail "no button in the panel"
read -r list_top list_bottom < <(runs scrolled.png 12 frame | awk -v t="$button_top" '$2 < t' | head -1) ||
  fail "no list above the screenshot button"
list_y=$(( (list_top + list_bottom) / 2 ))
button_y=$(( (button_top + button_bottom) / 2 ))
# Open the list: its popup covers the rows above or below it (the band
# watched ends there: the live numbers higher up change every frame).
band_top=$(( list_top > 90 ? list_top - 90 : 0 ))
band_bottom=$(( list_bottom + 90 < 400 ? list_bottom + 90 : 400 ))
click_until_changed 60 "$list_y" 175 $((band_bottom - band_top)) 8 "$band_top"
import -window "$wid" open.png
# The chosen row ("1x", header-coloured inside the popup, which is as wide
# as the list: not at x = 250, where a collapsing header would be); the rows
# follow at its height; "4x" is the third.
read -r row_top row_bottom < <(runs open.png 100 header 250 | head -1) || fail "no chosen row in the open list"
row_y=$(( (row_top + row_bottom) / 2 + 2 * (row_bottom - row_top + 1) ))
click_until_changed 60 "$row_y" 175 24 8 "$list_top"
# The window's frame, then the button: pressed until its pressed colour is
# drawn, released, and the poster is drawn at the next frame.
xdotool mousemove --window "$wid" 60 "$button_y"
settled 80 20 8 "$button_top"
settled 310 400 330 0
import -window "$wid" window.png
rm -f frustum-window-4x.png
hovered=$(region 80 20 8 "$button_top")
xdotool mousedown 1
changed_from "$hovered" 10 80 20 8 "$button_top" || fail "the screenshot button did not show its press in 10 s"
xdotool mouseup 1
# The poster appears whole (written atomically); its size must then stay.
for _ in $(seq 600); do
  if [ -f frustum-window-4x.png ]; then break; fi
  sleep 0.2
done
[ -f frustum-window-4x.png ] || fail "no frustum-window-4x.png within 120 s of the click"
last=-1
for _ in $(seq 50); do
  now=$(stat -c %s frustum-window-4x.png)
  if [ "$now" = "$last" ]; then break; fi
  last=$now
  sleep 0.2
done
[ "$now" = "$last" ] || fail "frustum-window-4x.png kept changing size"
xdotool key --window "$wid" Escape
wait "$pid"
trap - EXIT
)script";

} // namespace

TEST_SUITE("window") {

TEST_CASE("the panel's screenshot at 4x saves a poster 4x the window that, downsampled, is the window's frame") {
    const std::string xvfb_run = window_test::find_on_path("xvfb-run");
    if (xvfb_run.empty() || window_test::find_on_path("xdotool").empty() ||
        window_test::find_on_path("import").empty() || window_test::find_on_path("convert").empty()) {
        test_skips::skip("needs xvfb-run, xdotool and ImageMagick's import and convert (scripts/install-deps.sh --window)");
        return;
    }
    TempDir dir;
    const std::string script = (dir / "poster_button.sh").string();
    std::ofstream(script) << kScript;
    const window_test::Child child = window_test::run(
        xvfb_run, {"-a", "-s", "-screen 0 1024x768x24", "bash", script, window_test::kDemo, (dir / "").string()});
    REQUIRE_MESSAGE(child.exit_status == 0, child.err);

    const image::Image window = window_test::read(dir / "window.png");
    REQUIRE(window.width == kWindowWidthPx);
    REQUIRE(window.height == kWindowHeightPx);
    const image::Image poster = window_test::read(dir / "frustum-window-4x.png");
    // The chosen multiple of the window.
    CHECK(poster.width == kScale * kWindowWidthPx);
    CHECK(poster.height == kScale * kWindowHeightPx);
    REQUIRE(poster.width == kScale * window.width);
    REQUIRE(poster.height == kScale * window.height);

    // Box-filtered 4x (each pixel the mean of its 4 x 4 block), as a poster's thumbnail.
    image::Thumbnail small(poster.width, poster.height, kWindowWidthPx);
    small.add_rows(poster);
    REQUIRE(small.factor() == kScale);
    // Beside the panel (the poster has none) the window's frame. Tolerance
    // as test_poster_slow's 16384^2-downsampled-4x check (not equal: 16
    // pixels x 4 samples against the window's 4 samples, so edges differ by
    // some LSB): RGB means at most 1 LSB, at most 1% of the pixels more than
    // 24 LSB off. A poster of another view, size or crop differs in most
    // pixels.
    std::vector<bool> beside(static_cast<std::size_t>(window.width) * window.height, false);
    for (int y = 0; y < window.height; ++y) {
        for (int x = kPanelPx; x < window.width; ++x) {
            beside[static_cast<std::size_t>(y) * window.width + x] = true;
        }
    }
    const auto diff = image::compare_masked(window, small.image(), beside, image::Channels::Rgb, 24);
    REQUIRE_MESSAGE(diff.ok(), diff.error());
    MESSAGE("4x poster downsampled vs the window beside the panel: mean " << diff->mean_abs << " LSB, "
                                                                           << 100.0 * diff->fraction_over()
                                                                           << "% pixels over 24 LSB");
    CHECK(diff->mean_abs <= 1.0);
    CHECK(diff->fraction_over() <= 0.01);
}

} // TEST_SUITE
