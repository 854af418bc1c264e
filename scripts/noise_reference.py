#!/usr/bin/env python3
"""Renders each noise-based pattern alone with POV-Ray (grey value: ambient 1, diffuse 0,
linear 16-bit PPM, no anti-aliasing) on the planes z = 0.37 + 3.1 k (k = 0..3) seen
orthographically, 32 x 32 units at 512 x 512 pixels each (four slices, so that the
figures do not hang on one realisation of the noise), and writes the value quantiles and the radially averaged power
spectrum per octave band to tests/references/noise_stats.txt. tests/appearance_noise.rs
evaluates penumbra's patterns at the same pixel centres and compares.

Usage: scripts/noise_reference.py [NAME ...]   (needs povray and numpy)
With names, only those rows are measured again; the others are kept from the file.
"""
import os
import subprocess
import sys
import tempfile

import numpy as np

# The pattern bodies; the test holds the same list (names must match).
PATTERNS = {
    "bozo": "bozo",
    "spotted": "spotted",
    "granite": "granite",
    "marble": "marble turbulence 0.5",
    "wood": "wood turbulence 0.1 scale 4",
    "agate": "agate",
    "wrinkles": "wrinkles",
    "dents": "dents",
    "warp": "gradient x warp { turbulence 0.5 } scale 4",
    "bozo_ng1": "bozo noise_generator 1",
    "granite_ng1": "granite noise_generator 1",
    "wrinkles_ng1": "wrinkles noise_generator 1",
    "bozo_ng3": "bozo noise_generator 3",
    "granite_ng3": "granite noise_generator 3",
    "wrinkles_ng3": "wrinkles noise_generator 3",
    "bozo_turbulence": "bozo turbulence 0.6 octaves 7 omega 0.5 lambda 2.5",
    "bozo_turbulence_strong": "bozo turbulence 1.5 octaves 10 omega 0.5 lambda 2.5",
    "bozo_turbulence_one_octave": "bozo turbulence 0.5 octaves 1",
    "granite_turbulence": "granite turbulence 0.65 octaves 6 omega 0.7 lambda 2",
    "crackle": "crackle",
    "crackle_d1": "crackle form <1, 0, 0>",
    "crackle_d3": "crackle form <0, 0, 1>",
    "crackle_metric1": "crackle metric 1",
    "crackle_metric3": "crackle form <1, 0, 0> metric 3",
    "crackle_offset": "crackle offset 0.5",
    "crackle_solid": "crackle solid",
    # A quarter-unit scale puts 16 times as many cubes in the slices, so that the
    # quantiles of the one random value per cube settle (0.002 instead of 0.008).
    "cells": "cells scale 0.25",
}
SIZE = 512
EXTENT = 32.0
ZS = [0.37 + 3.1 * k for k in range(4)]
QUANTILES = [i / 20 for i in range(1, 20)]
# Octave bands in cycles per unit.
BANDS = [0.25, 0.5, 1.0, 2.0, 4.0, 8.0]


def read_ppm(path):
    data = open(path, "rb").read()
    pos, toks = 0, []
    while len(toks) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        toks.append(data[start:pos])
    pos += 1
    w, h, mx = int(toks[1]), int(toks[2]), int(toks[3])
    dtype = ">u2" if mx > 255 else "u1"
    arr = np.frombuffer(data[pos:], dtype=dtype)[: w * h * 3].reshape(h, w, 3)
    return arr[:, :, 0].astype(float) / mx


def band_powers(img):
    f = np.fft.fft2(img - img.mean())
    p = np.abs(f) ** 2 / img.size
    k = np.fft.fftfreq(SIZE, d=EXTENT / SIZE)
    kr = np.sqrt(k[None, :] ** 2 + k[:, None] ** 2)
    out = []
    for lo, hi in zip(BANDS[:-1], BANDS[1:]):
        sel = (kr >= lo) & (kr < hi)
        out.append(p[sel].mean())
    return out


def render(body, tmp, z):
    pov = os.path.join(tmp, "n.pov")
    ppm = os.path.join(tmp, "n.ppm")
    half = EXTENT / 2
    with open(pov, "w") as f:
        f.write(f"""#version 3.7;
global_settings {{ assumed_gamma 1.0 }}
camera {{ orthographic location <0,0,-1> look_at <0,0,0> right x*{EXTENT} up y*{EXTENT} }}
plane {{ z, {z} pigment {{ {body} color_map {{ [0 rgb 0] [1 rgb 1] }} }}
  finish {{ ambient 1 diffuse 0 }} }}
""")
    subprocess.run(
        ["povray", "-D", "-GA", "+FP16", "File_Gamma=1.0", "-A", f"+W{SIZE}", f"+H{SIZE}",
         f"+I{pov}", f"+O{ppm}"],
        check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return read_ppm(ppm)


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    out = os.path.join(root, "tests", "references", "noise_stats.txt")
    lines = ["# name | pattern body | 19 quantiles (5%..95%) | band powers "
             + " ".join(f"[{a},{b})" for a, b in zip(BANDS[:-1], BANDS[1:]))]
    only = set(sys.argv[1:])
    kept = {}
    if only and os.path.exists(out):
        for line in open(out):
            if not line.startswith("#") and "|" in line:
                kept[line.split("|")[0].strip()] = line.rstrip("\n")
    with tempfile.TemporaryDirectory() as tmp:
        for name, body in PATTERNS.items():
            if only and name not in only:
                if name in kept:
                    lines.append(kept[name])
                continue
            imgs = [render(body, tmp, z) for z in ZS]
            q = np.quantile(np.concatenate([i.ravel() for i in imgs]), QUANTILES)
            b = np.mean([band_powers(i) for i in imgs], axis=0)
            lines.append(f"{name} | {body} | " + " ".join(f"{v:.5f}" for v in q)
                         + " | " + " ".join(f"{v:.6e}" for v in b))
            print(lines[-1], file=sys.stderr)
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
