#!/usr/bin/env python3
"""Renders each noise-based normal (bumps, dents, wrinkles) alone with POV-Ray on the planes
z = 0.37 + 3.1 k (k = 0..15; 0..63 for dents), seen orthographically, 32 x 32 units at 512 x 512 pixels each,
white, `finish { ambient 0 diffuse 1 }`, linear 16-bit PPM, and writes to tests/references/normal_stats.txt:

- N.L with one parallel light along the view (the cosine of the tilt) at the amount in the
  body: 19 quantiles (5%..95%) and the radially averaged power spectrum in five octave bands
  (0.25 to 8 cycles per unit, averaged over the slices);
- the x slope of the perturbation, at amount 0.05 (small enough to be linear), divided by
  0.05: the same quantiles and bands. It comes from a second render with one light along
  the view (blue) and one at 45 degrees towards +x (red): slope = (sqrt 2 R - B) / B.

tests/appearance_normals.rs evaluates penumbra's normals at the same pixel centres.

Usage: scripts/normal_reference.py   (needs povray and numpy)
"""
import os
import subprocess
import sys
import tempfile

import numpy as np

# name: (pattern, amount for N.L, slices); the test reads the slice count from the file.
# Dents needs 16 slices: its fine bands come from the few highest noise peaks (the tilt
# grows as Noise^4), and povray's own band powers over three other sets of four slices
# ranged 0.69..1.03 (4-8 cycles) and 1.01..1.44 (1-2 cycles) of the first set's. Bumps
# too: its slope's 5% and 95% quantiles over four slices moved by up to 0.03 between
# sets of four (penumbra's max difference from povray's figure read 0.028 to 0.062 over
# four sets, the tolerance being 0.03), so all three take 16, and dents 64: over four sets
# of 16 slices penumbra's dents N.L band powers read 1.06-1.77 of povray's 16-slice figure
# (1.08-1.57 with the nineteenth session's noise).
NORMALS = {
    "bumps": ("bumps", 1.0, 16),
    "dents": ("dents", 2.0, 64),
    "wrinkles": ("wrinkles", 1.0, 16),
}
SLOPE_AMOUNT = 0.05
SIZE = 512
EXTENT = 32.0


def zs(slices):
    return [0.37 + 3.1 * k for k in range(slices)]
QUANTILES = [i / 20 for i in range(1, 20)]
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
    arr = np.frombuffer(data[pos:], dtype=">u2")[: w * h * 3].reshape(h, w, 3)
    return arr.astype(float) / mx


def band_powers(img):
    f = np.fft.fft2(img - img.mean())
    p = np.abs(f) ** 2 / img.size
    k = np.fft.fftfreq(SIZE, d=EXTENT / SIZE)
    kr = np.sqrt(k[None, :] ** 2 + k[:, None] ** 2)
    return [p[(kr >= lo) & (kr < hi)].mean() for lo, hi in zip(BANDS[:-1], BANDS[1:])]


def render(normal, tmp, z, side_light):
    pov = os.path.join(tmp, "n.pov")
    ppm = os.path.join(tmp, "n.ppm")
    side = "light_source { <1000,0,-1000> rgb <1,0,0> parallel point_at 0 }" if side_light else ""
    with open(pov, "w") as f:
        f.write(f"""#version 3.7;
global_settings {{ assumed_gamma 1.0 }}
camera {{ orthographic location <0,0,-10> look_at <0,0,0> right x*{EXTENT} up y*{EXTENT} }}
light_source {{ <0,0,-1000> rgb <0,0,1> parallel point_at 0 }}
{side}
plane {{ z, {z} pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 1 }} normal {{ {normal} }} }}
""")
    subprocess.run(["povray", "-D", "-GA", "+FP16", "File_Gamma=1.0", "-A", f"+W{SIZE}",
                    f"+H{SIZE}", f"+I{pov}", f"+O{ppm}"],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return read_ppm(ppm)


def stats(imgs):
    q = np.quantile(np.concatenate([i.ravel() for i in imgs]), QUANTILES)
    b = np.mean([band_powers(i) for i in imgs], axis=0)
    return " ".join(f"{v:.5f}" for v in q) + " | " + " ".join(f"{v:.6e}" for v in b)


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    out = os.path.join(root, "tests", "references", "normal_stats.txt")
    bands = " ".join(f"[{a},{b})" for a, b in zip(BANDS[:-1], BANDS[1:]))
    lines = [f"# name | pattern | amount | slices | N.L quantiles | N.L bands {bands} "
             "| x slope quantiles | x slope bands"]
    with tempfile.TemporaryDirectory() as tmp:
        for name, (pattern, amount, slices) in NORMALS.items():
            nl = [render(f"{pattern} {amount}", tmp, z, False)[..., 2] for z in zs(slices)]
            slopes = []
            for z in zs(slices):
                img = render(f"{pattern} {SLOPE_AMOUNT}", tmp, z, True)
                b = img[..., 2]
                slopes.append((np.sqrt(2.0) * img[..., 0] - b) / b / SLOPE_AMOUNT)
            lines.append(f"{name} | {pattern} | {amount} | {slices} | {stats(nl)} | {stats(slopes)}")
            print(lines[-1], file=sys.stderr)
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
