#!/usr/bin/env python3
"""POV-Ray's radiosity approaches penumbra's as its irradiance cache's quality rises.

For each scene in scenes/radiosity/: penumbra's converged image (two independent renders
of N spp, averaged; their difference gives the remaining noise), then POV-Ray at rising
radiosity quality (the rad_def.inc presets, with the scene's own recursion_limit written
after them, and settings beyond the presets), each rendered k = 2 times larger without
anti-aliasing and block-averaged. The RMSE between POV-Ray and penumbra at each quality is
the table; the chart draws it for the indirect light alone (each renderer's image less its
own image with radiosity off, so that the box filter's and the direct light's differences
cancel), against the floors: penumbra's own noise, and the RMSE of the two images with
radiosity off (what is not the cache's). Writes docs/convergence/radiosity/<scene>.csv,
<scene>.svg and a markdown table on stdout for docs/convergence.md.

    scripts/radiosity_convergence.py [--width 80 --height 60 --spp 1024 --timeout 900]
"""

import argparse
import array
import math
import os
import subprocess
import sys
import tempfile
import time

import Imath
import OpenEXR

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = ["cornell", "bleeding", "emission"]
# (label, POV-Ray declares), cheapest first.
QUALITIES = [
    ("Radiosity_Fast", ["Rad_Preset=2"]),
    ("Radiosity_Normal", ["Rad_Preset=3"]),
    ("Radiosity_Final", ["Rad_Preset=5"]),
    ("Radiosity_IndoorHQ", ["Rad_Preset=10"]),
    ("count 1000, error_bound 0.08", ["Rad_Count=1000", "Rad_Error=0.08",
                                      "Rad_Nearest=12", "Rad_Reuse=0.005",
                                      "Rad_Pretrace=0.005"]),
]
K = 2


def read_exr(path):
    f = OpenEXR.InputFile(path)
    dw = f.header()["dataWindow"]
    w, h = dw.max.x - dw.min.x + 1, dw.max.y - dw.min.y + 1
    pt = Imath.PixelType(Imath.PixelType.FLOAT)
    return w, h, [array.array("f", f.channel(c, pt)) for c in "RGB"]


def block_average(img, k):
    w, h, chans = img
    out = []
    for c in chans:
        o = [0.0] * ((w // k) * (h // k))
        for y in range(h):
            for x in range(w):
                o[(y // k) * (w // k) + x // k] += c[y * w + x]
        out.append([v / (k * k) for v in o])
    return w // k, h // k, out


def minus(a, b):
    return a[0], a[1], [[x - y for x, y in zip(ca, cb)] for ca, cb in zip(a[2], b[2])]


def rmse(a, b):
    s, n = 0.0, 0
    for ca, cb in zip(a[2], b[2]):
        for x, y in zip(ca, cb):
            s += (x - y) ** 2
            n += 1
    return math.sqrt(s / n)


def penumbra(scene, args, tmp, seed, spp, declares=()):
    out = os.path.join(tmp, f"pen_{seed}_{spp}.exr")
    cmd = [args.penumbra, "render", scene, "--width", str(args.width), "--height",
           str(args.height), "--spp", str(spp), "--seed", str(seed), "--output", out,
           "--quiet"]
    for d in declares:
        cmd += ["--declare", d]
    t = time.time()
    subprocess.run(cmd, check=True)
    return read_exr(out), time.time() - t


def povray(scene, args, tmp, declares):
    out = os.path.join(tmp, "pov.exr")
    cmd = ["povray", f"+I{scene}", f"+O{out}", "+FE", f"+W{args.width * K}",
           f"+H{args.height * K}", "-A", "-D", "-V", "-GA", "+Q9"]
    cmd += [f"Declare={d}" for d in declares]
    t = time.time()
    subprocess.run(cmd, check=True, timeout=args.timeout, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    return block_average(read_exr(out), K), time.time() - t


def svg_chart(path, title, points, floor, direct_floor, pen_points,
              direct_label="radiosity off (filter floor)"):
    """Log-log RMSE against seconds: POV-Ray's qualities, penumbra's spp, the floors."""
    xs = [p[1] for p in points + pen_points]
    floors = [(floor, "#888", "penumbra reference noise")]
    if direct_label:
        floors.append((direct_floor, "#c80", direct_label))
    ys = [p[2] for p in points + pen_points] + [y for y, _, _ in floors]
    x0, x1 = math.log10(min(xs)) - 0.2, math.log10(max(xs)) + 0.2
    y0, y1 = math.log10(max(min(ys), 1e-5)) - 0.2, math.log10(max(ys)) + 0.2
    W, H, m = 560, 360, 60
    def px(x): return m + (math.log10(x) - x0) / (x1 - x0) * (W - 2 * m)
    def py(y): return H - m - (math.log10(max(y, 1e-5)) - y0) / (y1 - y0) * (H - 2 * m)
    e = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" '
         f'font-family="sans-serif" font-size="11">',
         f'<rect width="{W}" height="{H}" fill="white"/>',
         f'<text x="{W/2}" y="18" text-anchor="middle" font-size="13">{title}</text>',
         f'<line x1="{m}" y1="{H-m}" x2="{W-m}" y2="{H-m}" stroke="black"/>',
         f'<line x1="{m}" y1="{m}" x2="{m}" y2="{H-m}" stroke="black"/>',
         f'<text x="{W/2}" y="{H-20}" text-anchor="middle">seconds (log)</text>',
         f'<text x="15" y="{H/2}" transform="rotate(-90 15 {H/2})" '
         f'text-anchor="middle">RMSE against penumbra converged (log)</text>']
    for d in range(math.floor(x0), math.ceil(x1) + 1):
        if x0 <= d <= x1:
            e.append(f'<text x="{px(10**d)}" y="{H-m+14}" text-anchor="middle">{10**d:g}</text>')
    for d in range(math.floor(y0), math.ceil(y1) + 1):
        if y0 <= d <= y1:
            e.append(f'<text x="{m-4}" y="{py(10**d)+4}" text-anchor="end">{10**d:g}</text>')
    for y, colour, label in floors:
        e.append(f'<line x1="{m}" y1="{py(y)}" x2="{W-m}" y2="{py(y)}" stroke="{colour}" '
                 f'stroke-dasharray="4 3"/><text x="{W-m}" y="{py(y)-3}" '
                 f'text-anchor="end" fill="{colour}">{label}</text>')
    for pts, colour, name in [(points, "#c00", "POV-Ray"), (pen_points, "#06c", "penumbra")]:
        path_d = " ".join(f"{'M' if i == 0 else 'L'}{px(t):.1f},{py(r):.1f}"
                          for i, (_, t, r) in enumerate(pts))
        e.append(f'<path d="{path_d}" fill="none" stroke="{colour}"/>')
        for label, t, r in pts:
            e.append(f'<circle cx="{px(t):.1f}" cy="{py(r):.1f}" r="3" fill="{colour}"/>'
                     f'<text x="{px(t)+5:.1f}" y="{py(r)-5:.1f}" fill="{colour}">{label}</text>')
    e.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(e))


def study(name, args, tmp):
    scene = os.path.join(ROOT, "scenes", "radiosity", f"{name}.pov")
    a, ta = penumbra(scene, args, tmp, 1, args.spp)
    b, tb = penumbra(scene, args, tmp, 2, args.spp)
    ref = (a[0], a[1], [[(x + y) / 2 for x, y in zip(ca, cb)] for ca, cb in zip(a[2], b[2])])
    noise = rmse(a, b) / 2  # the averaged reference's own noise
    off = ["No_Radiosity=1"]
    pov_off, _ = povray(scene, args, tmp, off)
    pen_off, _ = penumbra(scene, args, tmp, 1, args.spp, off)
    direct_floor = rmse(pov_off, pen_off)
    # The indirect light alone: each renderer's image less its own radiosity-off image, so
    # the box filter's and the direct light's differences cancel and the cache's remain.
    ref_indirect = minus(ref, pen_off)
    rows = []
    for label, declares in QUALITIES:
        try:
            img, t = povray(scene, args, tmp, declares)
        except subprocess.TimeoutExpired:
            print(f"{name}: {label} over {args.timeout} s, left out", file=sys.stderr)
            continue
        rows.append((label, t, rmse(minus(img, pov_off), ref_indirect), rmse(img, ref)))
        print(f"{name}: {label}: {t:.1f} s, RMSE {rows[-1][2]:.5f} {rows[-1][3]:.5f}",
              file=sys.stderr)
    pen = []
    for spp in args.pen_spp:
        img, t = penumbra(scene, args, tmp, 3, spp)
        pen.append((f"{spp} spp", t, rmse(img, ref)))
    out = os.path.join(ROOT, "docs", "convergence", "radiosity")
    with open(os.path.join(out, f"{name}.csv"), "w") as f:
        f.write("renderer,quality,seconds,rmse_indirect,rmse_image\n")
        for label, t, r, full in rows:
            f.write(f"povray,{label},{t:.2f},{r:.6f},{full:.6f}\n")
        for label, t, r in pen:
            f.write(f"penumbra,{label},{t:.2f},,{r:.6f}\n")
        f.write(f"floor,penumbra reference noise ({args.spp} spp x 2),{ta + tb:.2f},,{noise:.6f}\n")
        f.write(f"floor,radiosity off,,,{direct_floor:.6f}\n")
    svg_chart(os.path.join(out, f"{name}.svg"), f"scenes/radiosity/{name}.pov",
              [(label, t, r) for label, t, r, _ in rows], noise, direct_floor, pen)
    print(f"\nscenes/radiosity/{name}.pov ({args.width}x{args.height}; penumbra reference "
          f"2 x {args.spp} spp, {ta + tb:.0f} s, noise {noise:.5f}; radiosity off: "
          f"{direct_floor:.5f}), [chart](convergence/radiosity/{name}.svg):\n")
    print("| POV-Ray quality | seconds | RMSE, indirect light | RMSE, image |\n"
          "| --- | ---: | ---: | ---: |")
    for label, t, r, full in rows:
        print(f"| {label} | {t:.1f} | {r:.5f} | {full:.5f} |")
    print("\n| penumbra | seconds | RMSE |\n| --- | ---: | ---: |")
    for label, t, r in pen:
        print(f"| {label} | {t:.1f} | {r:.5f} |")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--width", type=int, default=80)
    p.add_argument("--height", type=int, default=60)
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
