#!/usr/bin/env python3
"""Renders turbulent fogs with POV-Ray and writes the quantiles of what they let through to
tests/references/fog_stats.txt; tests/fog_turbulence.rs renders the same scenes with
penumbra and compares. Each scene: a black plane 10 units behind a white fog, seen
orthographically over 20 x 20 units at 256 x 256 pixels (16-bit linear), so each pixel reads
the fog's attenuation a = 1 - value. Turbulence 2 puts about 1600 noise cells in view.

Usage: scripts/fog_reference.py   (needs povray and numpy)
"""
import os
import subprocess
import sys
import tempfile

import numpy as np

SIZE = 256
QUANTILES = [i / 20 for i in range(1, 20)]
# The fog bodies; the test reads them from the output, so the two cannot drift.
FOGS = {
    "constant": "distance 10 turbulence 2",
    "constant_one_octave": "distance 10 turbulence 2 octaves 1",
    "constant_deep": "distance 10 turbulence 2 turb_depth 1",
    "constant_thin": "distance 25 turbulence <2, 3, 2> omega 0.7 lambda 2.5 octaves 4",
    "ground": "fog_type 2 fog_offset 0 fog_alt 1 distance 5 turbulence 2",
}


def scene(body):
    return f"""#version 3.7;
global_settings {{ assumed_gamma 1 }}
camera {{ orthographic location <0, 1, 0> look_at <0, 1, 1> right x*20 up y*20 }}
plane {{ -z, -10 pigment {{ rgb 0 }} finish {{ ambient 1 diffuse 0 }} }}
fog {{ {body} color rgb 1 }}
"""


def render(body, tmp):
    pov, ppm = os.path.join(tmp, "f.pov"), os.path.join(tmp, "f.ppm")
    with open(pov, "w") as f:
        f.write(scene(body))
    subprocess.run(["povray", "-D", "-GA", "+FP16", "File_Gamma=1.0", "-A", f"+W{SIZE}",
                    f"+H{SIZE}", f"+I{pov}", f"+O{ppm}"], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    data = open(ppm, "rb").read()
    n = SIZE * SIZE * 3
    values = np.frombuffer(data[-2 * n:], dtype=">u2").reshape(SIZE, SIZE, 3)[:, :, 0]
    return 1.0 - values / 65535.0


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    out = os.path.join(root, "tests", "references", "fog_stats.txt")
    lines = ["# name | fog body (with `color rgb 1`) | 19 quantiles (5%..95%) of 1 - value"]
    with tempfile.TemporaryDirectory() as tmp:
        for name, body in FOGS.items():
            q = np.quantile(render(body, tmp), QUANTILES)
            lines.append(f"{name} | {body} | " + " ".join(f"{v:.5f}" for v in q))
            print(lines[-1], file=sys.stderr)
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
