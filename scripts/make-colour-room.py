#!/usr/bin/env python3
"""Writes textures/colour_room.hdr: a small equirectangular environment (256 x 128, Radiance RGBE) made
to test RGB-to-spectrum uplift with saturated colours. Around the horizon (+-20 degrees) the 24
patches of the ColorChecker (BabelColor's sRGB values, decoded to linear), above them a blue sky
darkening to the zenith, below a grey floor, and a warm lamp (a 3-degree disc, about 3000 K) at 50
degrees elevation. Synthetic on purpose: every colour is a published one.
Usage: scripts/make-colour-room.py [OUTPUT]"""
import math
import struct
import sys

CHECKER = [(115, 82, 68), (194, 150, 130), (98, 122, 157), (87, 108, 67), (133, 128, 177), (103, 189, 170),
           (214, 126, 44), (80, 91, 166), (193, 90, 99), (94, 60, 108), (157, 188, 64), (224, 163, 46),
           (56, 61, 150), (70, 148, 73), (175, 54, 60), (231, 199, 31), (187, 86, 149), (8, 133, 161),
           (243, 243, 242), (200, 200, 200), (160, 160, 160), (122, 122, 121), (85, 85, 85), (52, 52, 52)]


def linear(v8):
    v = v8 / 255.0
    return v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4


def radiance(theta, phi):
    """theta: elevation in radians, phi: azimuth in radians (0 at -Z, the image's centre)."""
    lamp = (math.radians(50.0), math.radians(-60.0))
    cos_d = (math.sin(theta) * math.sin(lamp[0]) + math.cos(theta) * math.cos(lamp[0]) * math.cos(phi - lamp[1]))
    if cos_d > math.cos(math.radians(3.0)):
        return (60.0, 38.0, 16.0)  # a warm lamp, roughly 3000 K in sRGB
    if abs(theta) <= math.radians(20.0):
        patch = CHECKER[int((phi + math.pi) / (2 * math.pi) * 24) % 24]
        return tuple(0.8 * linear(c) for c in patch)
    if theta > 0:
        t = (theta - math.radians(20.0)) / math.radians(70.0)
        return (0.30 * (1 - 0.5 * t), 0.45 * (1 - 0.4 * t), 0.95 * (1 - 0.3 * t))
    return (0.18, 0.17, 0.16)


def rgbe(r, g, b):
    m = max(r, g, b)
    if m < 1e-32:
        return bytes(4)
    mantissa, exponent = math.frexp(m)
    scale = mantissa * 256.0 / m
    return bytes((int(r * scale), int(g * scale), int(b * scale), exponent + 128))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "textures/colour_room.hdr"
    width, height = 256, 128
    rows = []
    for y in range(height):
        theta = math.pi / 2 - (y + 0.5) / height * math.pi
        row = b"".join(rgbe(*radiance(theta, (x + 0.5) / width * 2 * math.pi - math.pi)) for x in range(width))
        rows.append(row)
    with open(out, "wb") as f:
        f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n")
        f.write(("-Y %d +X %d\n" % (height, width)).encode())
        for row in rows:
            f.write(row)


if __name__ == "__main__":
    main()
