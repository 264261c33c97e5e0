#!/usr/bin/env bash
# The README's poster pictures (issue 36): a SIZE x SIZE poster of the
# showcase's mirror effect, rendered by frustum-demo render in tiles and
# streamed to disk, and two small PNGs under docs/images/:
#   poster-crop.png   a CROP x CROP window of the poster at full resolution
#                     (scripts/poster-crop.py reads the PNG row by row: the
#                     poster is never decoded whole, and ImageMagick refuses
#                     images over 16000 px per side by Debian's policy)
#   poster-whole.png  the whole frame, the same view rendered directly at
#                     WHOLE x WHOLE, with the crop's place outlined
#   scripts/poster-crop.sh DEMO [SIZE] [CROP] [X Y]   (defaults 16384, 512, and the crop's top-left)
set -euo pipefail
demo=$1
size=${2:-16384}
crop=${3:-512}
x=${4:-$((size * 300 / 1000))}
y=${5:-$((size * 455 / 1000))}
whole=512
images=$(cd "$(dirname "$0")/.." && pwd)/docs/images
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$demo" render --size "${size}x${size}" --effect mirror --out "$work/poster" >/dev/null
"$(dirname "$0")/poster-crop.py" "$work/poster/mirror.png" "$x" "$y" "$crop" "$crop" "$work/crop.rgba"
convert -size "${crop}x${crop}" -depth 8 "rgba:$work/crop.rgba" -strip "$images/poster-crop.png"

"$demo" render --size "${whole}x${whole}" --effect mirror --out "$work/whole" >/dev/null
scale_x0=$((x * whole / size)); scale_y0=$((y * whole / size))
scale_x1=$(((x + crop) * whole / size)); scale_y1=$(((y + crop) * whole / size))
convert "$work/whole/mirror.png" -fill none -stroke red -strokewidth 1 \
  -draw "rectangle $scale_x0,$scale_y0 $scale_x1,$scale_y1" -strip "$images/poster-whole.png"
echo "$images/poster-crop.png: ${crop}x${crop} at +${x}+${y} of the ${size}x${size} poster"
echo "$images/poster-whole.png: the frame at ${whole}x${whole}"
