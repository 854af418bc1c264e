#!/usr/bin/env python3
"""Compares penumbra with POV-Ray over an ensemble of noise phases, for scenes whose noise
texture is larger than the corpus judge's blocks (cloud skies): one phase says little there,
since POV-Ray's own image moves by more than the judge allows when the texture is shifted.

Each of N integer translations of the scene's sky_sphere (so that the noise lattice moves by
whole cells and its statistics stay the same) is rendered by both renderers at 160x120;
per channel, the image means of the two ensembles are compared with Welch's t. Writes one
markdown table row per scene.

Usage: scripts/phase_ensemble.py SCENE.pov [SCENE.pov ...]   (needs povray, numpy, pillow,
       and target/release/penumbra)
       scripts/phase_ensemble.py --shift 'TEXT' SCENE.pov: shift the noise by inserting
       `translate <dx, dy, dz>` after TEXT (the start of the noise pattern, so that the
       shift is in the noise's own units, before the pattern's scales) instead.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

import numpy as np
from PIL import Image

N = 8
INCLUDE = "/usr/share/povray-3.7/include"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PENUMBRA = os.path.join(ROOT, "target", "release", "penumbra")
SKY = re.compile(r"sky_sphere\s*\{\s*([A-Za-z_][A-Za-z_0-9]*)\s*\}")


def shifted(text, k, after=None):
    offset = f"<{7 * k}, {3 * k}, {5 * k}>"
    if after is not None:
        if after not in text:
            sys.exit(f"`{after}` is not in the scene")
        return text.replace(after, f"{after} translate {offset}", 1)
    out, n = SKY.subn(lambda m: f"sky_sphere {{ {m.group(1)} translate {offset} }}", text)
    if n == 0:
        sys.exit("no `sky_sphere { NAME }` to shift")
    return out


def mean_rgb(png):
    return np.asarray(Image.open(png).convert("RGB"), float).mean(axis=(0, 1)) / 255


def render_pair(scene, k, tmp, after):
    folder = os.path.dirname(os.path.abspath(scene))
    pov = os.path.join(tmp, f"phase{k}.pov")
    with open(scene, errors="replace") as f:
        text = f.read()
    with open(pov, "w") as f:
        f.write(shifted(text, k, after))
    a, b = os.path.join(tmp, f"pov{k}.png"), os.path.join(tmp, f"pen{k}.png")
    subprocess.run(["povray", "-D", "-A", "+W160", "+H120", f"+I{pov}", f"+O{a}",
                    f"+L{folder}", f"+L{INCLUDE}"], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    subprocess.run([PENUMBRA, "render", pov, "--width", "160", "--height", "120", "--spp",
                    "4", "--quiet", "-o", b, "-L", folder, "-L", INCLUDE], check=True)
    return mean_rgb(a), mean_rgb(b)


def main():
    print("| scene | channel | POV-Ray mean (sd) over phases | penumbra mean (sd) | t |")
    print("| --- | --- | --- | --- | ---: |")
    args = sys.argv[1:]
    after = None
    if args[:1] == ["--shift"]:
        after, args = args[1], args[2:]
    for scene in args:
        tmp = tempfile.mkdtemp()
        try:
            pairs = [render_pair(scene, k, tmp, after) for k in range(N)]
        finally:
            shutil.rmtree(tmp)
        pov = np.array([p for p, _ in pairs])
        pen = np.array([q for _, q in pairs])
        for c, name in enumerate("RGB"):
            a, b = pov[:, c], pen[:, c]
            se = np.sqrt(a.var(ddof=1) / N + b.var(ddof=1) / N)
            t = (b.mean() - a.mean()) / se if se > 0 else 0.0
            print(f"| {os.path.basename(scene)} | {name} | {a.mean():.3f} ({a.std(ddof=1):.3f})"
                  f" | {b.mean():.3f} ({b.std(ddof=1):.3f}) | {t:+.2f} |")


if __name__ == "__main__":
    main()
