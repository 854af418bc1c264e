#!/usr/bin/env python3
"""--target-error against fixed sample counts, on scenes with converged POV-Ray references.

For each scene: K seeds rendered with `--target-error E`, each compared with the committed
POV-Ray reference (tests/references/<scene>.exr); then fixed-spp renders (the same seeds)
at 8, 16, 32, ... spp until their RMSE falls below the target renders' mean RMSE, and the
spp and time of equal error interpolated in log-log between the two bracketing counts.
Prints a markdown table (docs/farm.md holds the last run). Usage:

    python3 scripts/target_error.py [--target 0.005] [--seeds 4] [--size 160x120]
"""

import argparse
import math
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PENUMBRA = os.environ.get("PENUMBRA", os.path.join(ROOT, "target/release/penumbra"))
SCENES = ["soft_shadow", "area_illumination", "glass"]


def render(scene, out, size, seed, extra):
    w, h = size
    cmd = [PENUMBRA, "render", os.path.join(ROOT, "scenes", scene + ".pov"),
           "--width", str(w), "--height", str(h), "--seed", str(seed), "-o", out] + extra
    start = time.monotonic()
    done = subprocess.run(cmd, capture_output=True, text=True, check=True)
    wall = time.monotonic() - start
    samples = int(re.search(r"(\d+) samples", done.stderr).group(1))
    return wall, samples / (w * h)


def rmse(image, scene):
    ref = os.path.join(ROOT, "tests/references", scene + ".exr")
    out = subprocess.run([PENUMBRA, "compare", image, ref], capture_output=True, text=True,
                         check=True).stdout
    return float(re.search(r"RMSE ([0-9.e-]+)", out).group(1))


def runs(scene, size, seeds, extra, tmp):
    """Mean RMSE, wall time and spp over the seeds."""
    figures = []
    for seed in range(1, seeds + 1):
        out = os.path.join(tmp, f"{scene}-{seed}.exr")
        wall, spp = render(scene, out, size, seed, extra)
        figures.append((rmse(out, scene), wall, spp))
    return [sum(f[i] for f in figures) / len(figures) for i in range(3)]


def equal_error(fixed, goal):
    """spp and time where the fixed renders' RMSE crosses `goal` (log-log between points)."""
    for (e0, t0, s0), (e1, t1, s1) in zip(fixed, fixed[1:]):
        if e1 <= goal <= e0:
            f = math.log(e0 / goal) / math.log(e0 / e1) if e0 != e1 else 0.0
            return s0 * (s1 / s0) ** f, t0 * (t1 / t0) ** f
    return None, None


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--target", type=float, default=0.005)
    p.add_argument("--seeds", type=int, default=4)
    p.add_argument("--size", default="160x120")
    a = p.parse_args()
    size = tuple(int(x) for x in a.size.split("x"))
    print(f"--target-error {a.target}, {a.size}, {a.seeds} seeds each, means; RMSE against "
          "the committed POV-Ray reference")
    print()
    print("| scene | target: RMSE | spp | time | fixed spp of equal RMSE | its time | "
          "fixed renders (spp: RMSE) |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    with tempfile.TemporaryDirectory() as tmp:
        for scene in SCENES:
            e, t, s = runs(scene, size, a.seeds, ["--target-error", str(a.target)], tmp)
            fixed = []
            spp = 8
            while spp <= 4096:
                fe, ft, _ = runs(scene, size, a.seeds, ["--spp", str(spp)], tmp)
                fixed.append((fe, ft, spp))
                if fe < e:
                    break
                spp *= 2
            es, et = equal_error(fixed, e)
            cells = ", ".join(f"{s_}: {e_:.5f}" for e_, _, s_ in fixed)
            eq = f"{es:.1f} | {et:.2f} s" if es else "not reached | -"
            print(f"| {scene} | {e:.5f} | {s:.1f} | {t:.2f} s | {eq} | {cells} |")
            sys.stdout.flush()


if __name__ == "__main__":
    main()
