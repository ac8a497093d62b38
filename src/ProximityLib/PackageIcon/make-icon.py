#!/usr/bin/env python3
"""Draws the NuGet package icon (icon.png beside this file): a sphere and a turned box joined by the closest-distance
line, in the picker's colours. Standard library only; run it again after changing the drawing."""
import math, os, struct, zlib

SIZE, SS = 128, 4  # pixels, supersampling per axis (anti-aliasing)
SPHERE = ((34, 78), 24, (214, 39, 40))                       # centre, radius, colour (the gait plot's heel red)
BOX = ((90, 46), math.radians(30), (24, 16), (31, 119, 180))  # centre, angle, half-extents, colour (toe blue)
LINE = (255, 200, 0)                                          # the picker's yellow closest-distance line

def in_box(x, y):
    (cx, cy), a, (hx, hy), _ = BOX
    dx, dy = x - cx, y - cy
    u, v = dx * math.cos(a) + dy * math.sin(a), -dx * math.sin(a) + dy * math.cos(a)
    return abs(u) <= hx and abs(v) <= hy

def box_closest(px, py):
    (cx, cy), a, (hx, hy), _ = BOX
    dx, dy = px - cx, py - cy
    u, v = dx * math.cos(a) + dy * math.sin(a), -dx * math.sin(a) + dy * math.cos(a)
    u, v = max(-hx, min(hx, u)), max(-hy, min(hy, v))
    return cx + u * math.cos(a) - v * math.sin(a), cy + u * math.sin(a) + v * math.cos(a)

# Closest points: the box point nearest the sphere centre, and the sphere point towards it.
(sx, sy), r, _ = SPHERE
bx, by = box_closest(sx, sy)
d = math.hypot(bx - sx, by - sy)
ax, ay = sx + (bx - sx) / d * r, sy + (by - sy) / d * r

def near_segment(x, y, w):
    tx, ty = bx - ax, by - ay
    t = max(0.0, min(1.0, ((x - ax) * tx + (y - ay) * ty) / (tx * tx + ty * ty)))
    return math.hypot(x - (ax + t * tx), y - (ay + t * ty)) <= w

def colour(x, y):  # RGBA of one sample, painted back to front
    if near_segment(x, y, 3.2):
        return LINE + (255,)
    if math.hypot(x - sx, y - sy) <= r:
        return SPHERE[2] + (255,)
    if in_box(x, y):
        return BOX[3] + (255,)
    return (0, 0, 0, 0)

rows = []
for py in range(SIZE):
    row = bytearray([0])  # PNG filter: none
    for px in range(SIZE):
        acc = [0, 0, 0, 0]
        for j in range(SS):
            for i in range(SS):
                c = colour(px + (i + 0.5) / SS, py + (j + 0.5) / SS)
                for k in range(3):
                    acc[k] += c[k] * c[3]
                acc[3] += c[3]
        alpha = acc[3] / (SS * SS)
        rgb = [round(acc[k] / acc[3]) if acc[3] else 0 for k in range(3)]
        row += bytes(rgb + [round(alpha)])
    rows.append(bytes(row))

def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", SIZE, SIZE, 8, 6, 0, 0, 0)) \
    + chunk(b"IDAT", zlib.compress(b"".join(rows), 9)) + chunk(b"IEND", b"")
with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "icon.png"), "wb") as f:
    f.write(png)
