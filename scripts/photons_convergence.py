#!/usr/bin/env python3
"""POV-Ray's caustics approach penumbra's as its photon count rises.

For each scene in scenes/photons/: penumbra's converged image (two independent renders of
N spp, averaged; their difference gives the remaining noise), then POV-Ray at rising photon
counts and gather ranges (the scene reads `Photon_Count` and
`Photon_Gather`), each rendered k = 2 times larger without
anti-aliasing and block-averaged. The RMSE between POV-Ray and penumbra at each count is
the table and the chart, against penumbra's own noise floor and the two renderers' RMSE on
the same scene with no photon target (what is not the photon map's: the box filter and the
direct light). Writes docs/convergence/photons/<scene>.csv, <scene>.svg and a markdown
table on stdout for docs/convergence.md.

    scripts/photons_convergence.py [--width 160 --height 120 --spp 1024 --timeout 900]
"""

import argparse
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from radiosity_convergence import ROOT, penumbra, povray, rmse, svg_chart  # noqa: E402

SCENES = ["caustics", "media_caustic"]
# What a scene asks of POV-Ray beside the photons: media_caustic's quadrature converged
# (the scene's Media_Converged), and no more than 10^6 photons there (POV-Ray takes minutes
# per image with its media photons, and 10^7 took 8.1 GB).
POVRAY_DECLARES = {"media_caustic": ["Media_Converged=1"]}
MAX_COUNT = {"media_caustic": 1_000_000}
# POV-Ray's quality: the photon count with the gather range (min, 5 min) raised beside it.
# The count alone does not converge: with the default gather 20, 100 each pixel still
# averages at most 100 photons, so its noise stays while its radius shrinks (measured:
# RMSE against penumbra 0.080 at 10^6, 0.118 at 10^7, 0.159 at 3 x 10^7 photons).
QUALITIES = [(10_000, 20), (100_000, 20), (1_000_000, 60), (10_000_000, 200),
             (30_000_000, 350)]


def display_rmse(a, b):
    """RMSE of the values a PNG shows (clamped to 1): the caustic's cusp, where the
    radiance is unbounded and POV-Ray's 4 point samples per pixel scatter widely, does not
    drown the rest of the image."""
    s, n = 0.0, 0
    for ca, cb in zip(a[2], b[2]):
        for x, y in zip(ca, cb):
            s += (min(x, 1.0) - min(y, 1.0)) ** 2
            n += 1
    return (s / n) ** 0.5


def study(name, args, tmp):
    scene = os.path.join(ROOT, "scenes", "photons", f"{name}.pov")
    a, ta = penumbra(scene, args, tmp, 1, args.spp)
    b, tb = penumbra(scene, args, tmp, 2, args.spp)
    ref = (a[0], a[1], [[(x + y) / 2 for x, y in zip(ca, cb)] for ca, cb in zip(a[2], b[2])])
    noise = display_rmse(a, b) / 2
    rows = []
    for count, gather in QUALITIES:
        if count > MAX_COUNT.get(name, count):
            continue
        declares = [f"Photon_Count={count}", f"Photon_Gather={gather}"]
        try:
            img, t = povray(scene, args, tmp, declares + POVRAY_DECLARES.get(name, []))
        except subprocess.TimeoutExpired:
            print(f"{name}: {count} photons over {args.timeout} s, left out", file=sys.stderr)
            continue
        rows.append((f"{count:.0e} photons / gather {gather}", t, display_rmse(img, ref),
                     rmse(img, ref)))
        print(f"{name}: {rows[-1]}", file=sys.stderr)
    pen = []
    for spp in args.pen_spp:
        img, t = penumbra(scene, args, tmp, 3, spp)
        pen.append((f"{spp} spp", t, display_rmse(img, ref), rmse(img, ref)))
    out = os.path.join(ROOT, "docs", "convergence", "photons")
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, f"{name}.csv"), "w") as f:
        f.write("renderer,quality,seconds,rmse_display,rmse_linear\n")
        for label, t, r, lin in rows:
            f.write(f"povray,{label},{t:.2f},{r:.6f},{lin:.6f}\n")
        for label, t, r, lin in pen:
            f.write(f"penumbra,{label},{t:.2f},{r:.6f},{lin:.6f}\n")
        f.write(f"floor,penumbra reference noise ({args.spp} spp x 2),{ta + tb:.2f},"
                f"{noise:.6f},{rmse(a, b) / 2:.6f}\n")
    svg_chart(os.path.join(out, f"{name}.svg"), f"scenes/photons/{name}.pov (display RMSE)",
              [r[:3] for r in rows], noise, noise, [r[:3] for r in pen], direct_label=None)
    print(f"\nscenes/photons/{name}.pov ({args.width}x{args.height}; penumbra reference "
          f"2 x {args.spp} spp, {ta + tb:.0f} s, noise {noise:.5f}), "
          f"[chart](convergence/photons/{name}.svg):\n")
    print("| POV-Ray quality | seconds | RMSE (display) | RMSE (linear) |\n"
          "| --- | ---: | ---: | ---: |")
    for label, t, r, lin in rows:
        print(f"| {label} | {t:.1f} | {r:.5f} | {lin:.5f} |")
    print("\n| penumbra | seconds | RMSE (display) | RMSE (linear) |\n"
          "| --- | ---: | ---: | ---: |")
    for label, t, r, lin in pen:
        print(f"| {label} | {t:.1f} | {r:.5f} | {lin:.5f} |")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--width", type=int, default=160)
    p.add_argument("--height", type=int, default=120)
    p.add_argument("--spp", type=int, default=1024)
    p.add_argument("--pen-spp", type=int, nargs="*", default=[4, 16, 64, 256])
    p.add_argument("--timeout", type=float, default=900)
    p.add_argument("--scenes", nargs="*", default=SCENES)
    target = os.environ.get("CARGO_TARGET_DIR", os.path.join(ROOT, "target"))
    p.add_argument("--penumbra", default=os.path.join(target, "release", "penumbra"))
    args = p.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        for name in args.scenes:
            study(name, args, tmp)


if __name__ == "__main__":
    main()
