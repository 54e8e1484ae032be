#!/usr/bin/env python3
"""Fine detail of rendered images: the mean absolute Laplacian of luminance.

Usage: scripts/image_detail.py IMAGE.png [REFERENCE.png]

Prints the image's mean |Laplacian| (4-neighbour, of the Rec. 709 luminance of the 8-bit display
values, interior pixels) and, with a reference (e.g. the `exact` preset's render of the same camera),
the ratio of the two: how much of the reference's fine detail the image keeps (docs/rendering.md,
"Surface textures"). Reads 8-bit, non-interlaced RGB or RGBA PNG files (what `globe render` writes)
with the standard library only. A file it cannot read is a one-line error and exit status 1.
"""
import struct
import sys
import zlib


def read_png(path):
    """Rows of (r, g, b) tuples of an 8-bit, non-interlaced RGB/RGBA PNG."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG file")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    if header is None:
        raise ValueError("no IHDR chunk")
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace != 0:
        raise ValueError("only 8-bit non-interlaced RGB or RGBA PNG files are read")
    channels = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up = previous[i]
            corner = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + left) & 0xFF
            elif kind == 2:
                line[i] = (line[i] + up) & 0xFF
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 0xFF
            elif kind == 4:
                p = left + up - corner
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else corner)) & 0xFF
        rows.append(line)
        previous = line
    return width, height, [[(r[x * channels], r[x * channels + 1], r[x * channels + 2]) for x in range(width)]
                           for r in rows]


def mean_abs_laplacian(path):
    width, height, rows = read_png(path)
    lum = [[(0.2126 * r + 0.7152 * g + 0.0722 * b) / 255.0 for (r, g, b) in row] for row in rows]
    total = 0.0
    for y in range(1, height - 1):
        above, here, below = lum[y - 1], lum[y], lum[y + 1]
        for x in range(1, width - 1):
            total += abs(above[x] + below[x] + here[x - 1] + here[x + 1] - 4.0 * here[x])
    return total / ((width - 2) * (height - 2))


def main(argv):
    if len(argv) not in (2, 3):
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    values = []
    for path in argv[1:]:
        try:
            values.append(mean_abs_laplacian(path))
        except (OSError, ValueError, zlib.error) as e:
            print(f"{path}: {e}", file=sys.stderr)
            return 1
    print(f"mean |laplacian| {values[0]:.6f}")
    if len(values) == 2:
        print(f"reference {values[1]:.6f}, ratio {values[0] / values[1]:.3f}" if values[1] > 0 else "reference 0")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
