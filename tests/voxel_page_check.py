"""Checks a screenshot of the voxel world's 3D page (tests/voxel_page_in_chromium.sh): the
picture right of the legend panel must show the path, the start, the goal and the voxels in
their colours (drawing/src/voxel_colours.hpp), lit, so told apart by hue.

    python3 voxel_page_check.py SCREENSHOT.png [PANEL_RIGHT_EDGE]

The standard library only: the PNG is decoded here (8-bit RGB or RGBA, not interlaced)."""
import colorsys
import struct
import sys
import zlib


def read_png(path):
    data = open(path, 'rb').read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        sys.exit(f'{path} is not a PNG')
    pos, idat, header = 8, b'', None
    while pos < len(data):
        length, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b'IHDR':
            header = struct.unpack('>IIBBBBB', body)
        elif kind == b'IDAT':
            idat += body
    width, height, depth, colour_type, _, _, interlace = header
    if depth != 8 or colour_type not in (2, 6) or interlace:
        sys.exit(f'{path}: unsupported PNG (bit depth {depth}, colour type {colour_type}, interlace {interlace})')
    channels = 3 if colour_type == 2 else 4
    raw, stride = zlib.decompress(idat), width * channels
    rows, previous, i = [], bytearray(stride), 0
    for _ in range(height):
        kind, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b = previous[x]
            c = previous[x - channels] if x >= channels else 0
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        previous = line
    return width, height, channels, rows


def classify(r, g, b):
    """The page's colour a pixel is, by hue (lighting scales brightness, not hue), or None."""
    h, s, v = colorsys.rgb_to_hsv(r / 255, g / 255, b / 255)
    hue = h * 360
    if v < 0.2:
        return None
    if s > 0.6 and (hue < 12 or hue > 348):
        return 'goal'  # #e53935
    if s > 0.7 and 22 <= hue <= 42:
        return 'path'  # #f57c00
    if s > 0.4 and 100 <= hue <= 140:
        return 'start'  # #43a047
    if 0.12 <= s <= 0.5 and 185 <= hue <= 215:
        return 'voxel'  # #455a64 to #90a4ae
    return None


def main():
    path = sys.argv[1]
    left = int(sys.argv[2]) if len(sys.argv) > 2 else 0
    width, height, channels, rows = read_png(path)
    counts = {'goal': 0, 'path': 0, 'start': 0, 'voxel': 0}
    for row in rows:
        for x in range(left, width):
            kind = classify(*row[x * channels:x * channels + 3])
            if kind:
                counts[kind] += 1
    print(f'{path}: {width}x{height}, pixels right of x = {left}: ' +
          ', '.join(f'{kind} {n}' for kind, n in counts.items()))
    needed = {'goal': 40, 'path': 200, 'start': 40, 'voxel': 5000}
    missing = [kind for kind, n in needed.items() if counts[kind] < n]
    if missing:
        sys.exit('too few pixels of ' + ', '.join(f'{kind} (needs {needed[kind]})' for kind in missing))


main()
