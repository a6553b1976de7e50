#!/usr/bin/env python3
"""Writes the 'photographed sky' of docs/brdf.md: an equirectangular Radiance .hdr, 512x256, a blue
dome brightening towards the horizon (about 2 of irradiance on a horizontal plane), a dark ground and
a sun 1 degree across at 35 degrees elevation with 25 of irradiance facing it. Only the standard
library: python3 scripts/photographed-sky.py OUT.hdr [--no-sun]."""
import math
import sys

WIDTH, HEIGHT = 512, 256
SUN_ELEVATION, SUN_RADIUS = math.radians(35), math.radians(0.5)
SUN_RADIANCE = 25.0 / (2 * math.pi * (1 - math.cos(SUN_RADIUS)))


def direction(x, y):
    # fxview's equirectangular convention (viewer/lighting): the image's centre looks down -Z, +Y up.
    phi, theta = ((x + 0.5) / WIDTH - 0.5) * 2 * math.pi, (y + 0.5) / HEIGHT * math.pi
    return (math.sin(theta) * math.sin(phi), math.cos(theta), -math.sin(theta) * math.cos(phi))


def radiance(d, sun):
    if sun and d[1] * math.sin(SUN_ELEVATION) - d[2] * math.cos(SUN_ELEVATION) > math.cos(SUN_RADIUS):
        return (SUN_RADIANCE,) * 3
    if d[1] < 0:
        return (0.05, 0.045, 0.04)  # dark ground
    horizon = 1 - d[1]  # 0 at the zenith, 1 at the horizon
    return tuple(c * (0.45 + 0.75 * horizon * horizon) for c in (0.35, 0.55, 1.0))


def rgbe(rgb):
    top = max(rgb)
    if top < 1e-32:
        return bytes(4)
    mantissa, exponent = math.frexp(top)
    scale = mantissa * 256.0 / top
    return bytes([int(c * scale) for c in rgb] + [exponent + 128])


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    sun = "--no-sun" not in sys.argv[2:]
    data = bytearray(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (HEIGHT, WIDTH))
    for y in range(HEIGHT):
        for x in range(WIDTH):
            data += rgbe(radiance(direction(x, y), sun))
    with open(sys.argv[1], "wb") as out:
        out.write(data)


main()
