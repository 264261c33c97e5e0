#!/usr/bin/env python3
"""Cuts a W x H window out of a poster PNG without decoding it whole.

    scripts/poster-crop.py POSTER.png X Y W H OUT.rgba

ImageMagick refuses images over its policy's 16000 px per side (Debian's
/etc/ImageMagick-6/policy.xml), so the poster's rows are inflated here one
by one (zlib, streamed) and only the window's rows unfiltered. Handles
8-bit RGBA, non-interlaced PNGs whose rows use the "none" or "sub" filter,
as frustum-demo's posters do (image/png_stream.cpp); anything else is a
one-line error. Writes the window as raw RGBA bytes (for `convert rgba:`).
"""
import struct
import sys
import zlib


def fail(message):
    sys.exit("poster-crop.py: " + message)


def chunks(f):
    if f.read(8) != b"\x89PNG\r\n\x1a\n":
        fail("not a PNG")
    while True:
        head = f.read(8)
        if len(head) < 8:
            return
        length, kind = struct.unpack(">I4s", head)
        yield kind, f.read(length)
        f.read(4)  # CRC


def main():
    if len(sys.argv) != 7:
        fail("usage: poster-crop.py POSTER.png X Y W H OUT.rgba")
    path = sys.argv[1]
    x, y, w, h = (int(v) for v in sys.argv[2:6])
    with open(path, "rb") as f, open(sys.argv[6], "wb") as out:
        inflate = zlib.decompressobj()
        pending = b""
        row = 0
        width = height = stride = None
        for kind, data in chunks(f):
            if kind == b"IHDR":
                width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", data)
                if depth != 8 or colour != 6 or interlace != 0:
                    fail(f"'{path}': needs 8-bit RGBA without interlace")
                if x < 0 or y < 0 or w < 1 or h < 1 or x + w > width or y + h > height:
                    fail(f"window {w}x{h}+{x}+{y} is not inside the {width}x{height} image")
                stride = width * 4 + 1
            elif kind == b"IDAT":
                pending += inflate.decompress(data)
                while len(pending) >= stride and row < y + h:
                    line, pending = pending[:stride], pending[stride:]
                    if line[0] not in (0, 1):
                        fail(f"'{path}': row {row} uses PNG filter {line[0]}, only none (0) and sub (1) are read")
                    if row >= y:
                        end = (x + w) * 4
                        pixels = bytearray(line[1:end + 1])
                        if line[0] == 1:
                            for i in range(4, end):
                                pixels[i] = (pixels[i] + pixels[i - 4]) & 255
                        out.write(pixels[x * 4:end])
                    row += 1
                if row >= y + h:
                    return
        fail(f"'{path}': image data ended at row {row}")


main()
