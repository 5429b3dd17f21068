#!/usr/bin/env python3
"""Checks on the viewer's screenshots, standard library only (no numpy, no PIL).

png_check.py organ A.png      the picture is not one colour and the organ covers 5-95 % of it
png_check.py differ A.png B.png [LEVELS COUNT]
                                  at least COUNT (100) pixels differ by more than LEVELS (24) in a channel
png_check.py steel A.png MINX COUNT
                                  at least COUNT steel-grey pixels (the instrument: channels within 14
                                  levels, mean 70..235) right of column MINX (left of it: the panel's text)
png_check.py panel A.png COUNT    at least COUNT pixels of ImGui's dark style: the focused title bar
                                  (41, 74, 122) and the frame background (29, 47, 73), within 4 levels
png_check.py softer A.png B.png   inside the organ (both pictures off the background), A's detail
                                  (mean |4-neighbour Laplacian| of the green channel) is below 0.8
                                  of B's: subsurface scattering blurs the normal-mapped surface
"""
import struct
import sys
import zlib


def read_png(path):
    """8-bit RGB or RGBA PNG, non-interlaced -> (width, height, channels, rows of bytes)."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"FAIL: {path} is not a PNG")
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, color, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or color not in (2, 6) or interlace:
                sys.exit(f"FAIL: {path}: expected 8-bit RGB(A), non-interlaced")
            channels = 3 if color == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, rows, prev = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):  # undo the PNG row filter (RFC 2083 §6)
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, channels, rows


def pixels(path):
    w, h, ch, rows = read_png(path)
    return w, h, [tuple(r[x * ch:x * ch + 3]) for r in rows for x in range(w)]


def main():
    if sys.argv[1] == "organ":
        w, h, px = pixels(sys.argv[2])
        background = px[0]
        colours = len(set(px))
        covered = sum(1 for p in px if max(abs(a - b) for a, b in zip(p, background)) > 24) / len(px)
        print(f"{sys.argv[2]}: {w}x{h}, {colours} colours, organ covers {covered:.1%}")
        if colours < 100 or not 0.05 < covered < 0.95:
            sys.exit("FAIL: no organ in the picture")
    elif sys.argv[1] == "differ":
        wa, ha, a = pixels(sys.argv[2])
        wb, hb, b = pixels(sys.argv[3])
        if (wa, ha) != (wb, hb):
            sys.exit("FAIL: the pictures differ in size")
        levels, count = (int(sys.argv[4]), int(sys.argv[5])) if len(sys.argv) > 5 else (24, 100)
        changed = sum(1 for p, q in zip(a, b) if max(abs(x - y) for x, y in zip(p, q)) > levels)
        print(f"{changed} pixels differ by more than {levels} levels")
        if changed < count:
            sys.exit(f"FAIL: fewer than {count} pixels changed")
    elif sys.argv[1] == "steel":
        w, h, px = pixels(sys.argv[2])
        min_x, count = int(sys.argv[3]), int(sys.argv[4])
        steel = sum(1 for i, p in enumerate(px)
                    if i % w >= min_x and max(p) - min(p) <= 14 and 70 <= sum(p) / 3 <= 235)
        print(f"{sys.argv[2]}: {steel} steel-grey pixels right of x = {min_x}")
        if steel < count:
            sys.exit(f"FAIL: fewer than {count} steel-grey pixels: no instrument in the picture")
    elif sys.argv[1] == "panel":
        w, h, px = pixels(sys.argv[2])
        styled = sum(1 for p in px if any(all(abs(a - b) <= 4 for a, b in zip(p, c))
                                          for c in ((41, 74, 122), (29, 47, 73))))
        print(f"{sys.argv[2]}: {styled} pixels in ImGui's panel colours")
        if styled < int(sys.argv[3]):
            sys.exit("FAIL: no ImGui panel in the picture")
    elif sys.argv[1] == "softer":
        detail = []
        wa, ha, a = pixels(sys.argv[2])
        wb, hb, b = pixels(sys.argv[3])
        if (wa, ha) != (wb, hb):
            sys.exit("FAIL: the pictures differ in size")
        bg = a[0]

        def inside(px, i):
            return max(abs(x - y) for x, y in zip(px[i], bg)) > 24

        for px in (a, b):
            total, count = 0, 0
            for y in range(1, ha - 1):
                for x in range(1, wa - 1):
                    i = y * wa + x
                    ring = (i - 1, i + 1, i - wa, i + wa)
                    if not all(inside(a, j) and inside(b, j) for j in (i,) + ring):
                        continue
                    total += abs(4 * px[i][1] - sum(px[j][1] for j in ring))
                    count += 1
            detail.append(total / max(count, 1))
        print(f"detail {detail[0]:.2f} against {detail[1]:.2f}")
        if detail[0] >= 0.8 * detail[1]:
            sys.exit("FAIL: not softer than the lit picture")


if __name__ == "__main__":
    main()
