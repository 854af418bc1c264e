#!/usr/bin/env python3
"""Measures POV-Ray 3.7's focal-blur lens for a `blur_samples` count.

A small bright sphere far out of focus images the lens, point-mirrored and magnified 9x
(camera at the origin looking along +z, focus at z = 10, the sphere at z = 1). Each render
of the sphere, with `variance 0` so every lens sample is taken, is a sample of the lens's
density convolved with the sphere's disc; several renders with the sphere moved (so that
other pixels, with other jitter, see it) are fitted together by least squares to a model of
equal squares, one a sample, each jittered whole: the seven points of the one-ring
hexagonal grid (a spacing and a row height) plus the rest placed freely (from a greedy
start). Squares that overlap much leave local minima: `--starts N` refits N times from the
best fit with two squares moved at random and keeps the lowest sum of squares, and
`--table FILE` starts from given centres. src/render/camera.rs's 16-sample lens is the best
of such starts (four renders at 4000: SSE 238,866 against 240,598 from the greedy start).
Prints the squares' side and centres in aperture units, x along right, y along up.

Usage: lens_fit.py COUNT [--aspect 1.3333] [--aperture 1] [--angle 60] [--focal 10]
                         [--size 4000] [--renders 4] [--starts 0] [--table FILE]
Needs povray, numpy, scipy, pillow. Renders go to /tmp/lens_fit.
"""
import argparse, os, subprocess
import numpy as np
from numpy.fft import rfft2, irfft2
from PIL import Image
from scipy.ndimage import uniform_filter
from scipy.optimize import least_squares

SCENE = """#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location 0 direction z right x*ASPECT up y angle ANGLE
  aperture APERTURE blur_samples COUNT variance 0 focal_point <0, 0, FOCAL> }
sphere { <SX, SY, NEAR>, RADIUS pigment { rgb 1 } finish { ambient 1 diffuse 0 } }
"""
BIN = 4


def render(a, sx, sy, radius, work):
    text = SCENE
    for k, v in dict(ANGLE=a.angle, FOCAL=a.focal, NEAR=a.focal / 10, ASPECT=a.aspect, APERTURE=a.aperture, COUNT=a.count, SX=sx, SY=sy,
                     RADIUS=radius).items():
        text = text.replace(k, repr(v))
    pov = os.path.join(work, 'lens.pov')
    open(pov, 'w').write(text)
    out = os.path.join(work, f'lens_{a.count}_{sx}_{sy}.png')
    w, h = round(a.size * a.aspect / BIN) * BIN, a.size
    subprocess.run(['povray', f'+I{pov}', f'+O{out}', f'+W{w}', f'+H{h}', '-A', '+FN16',
                    '-D', '-V', '-GA'], check=True, capture_output=True)
    v = np.asarray(Image.open(out)).astype(float)[..., 0]
    # One hit in COUNT samples encodes as 1/COUNT through the file's gamma 2.
    unit = np.sort(np.unique(v))[1]
    return np.round((v / unit) ** 2)


def disc_kernel(rho):
    r = int(np.ceil(rho)) + 1
    yy, xx = np.mgrid[-r:r + 1, -r:r + 1]
    k = np.zeros_like(xx, dtype=float)
    for sy in range(8):
        for sx in range(8):
            k += (xx + (sx + .5) / 8 - .5) ** 2 + (yy + (sy + .5) / 8 - .5) ** 2 <= rho * rho
    return k / k.sum(), r


def overlap(c, s, n):
    e = np.arange(n + 1, dtype=float)
    lo = np.clip(e[:-1], c - s / 2, c + s / 2)
    hi = np.clip(e[1:], c - s / 2, c + s / 2)
    return np.maximum(hi - lo, 0)


def hexagon(spacing, row):
    return [(0, 0), (-spacing, 0), (spacing, 0), (-spacing / 2, row), (spacing / 2, row),
            (-spacing / 2, -row), (spacing / 2, -row)]


class Data:
    def __init__(self, hits, sx, sy, a, radius):
        b = hits.reshape(hits.shape[0] // BIN, BIN, hits.shape[1] // BIN, BIN).sum(axis=(1, 3))
        self.W, self.H = b.shape[1], b.shape[0]
        self.scale = self.W / (2 * np.tan(np.radians(a.angle / 2)) * a.focal)  # bins per focal-plane unit
        ys, xs = np.nonzero(b)
        self.y0, self.x0 = ys.min() - 10, xs.min() - 10
        self.b = b[self.y0:ys.max() + 11, self.x0:xs.max() + 11].astype(float)
        h, w = self.b.shape
        ker, r = disc_kernel(radius * 10 * self.scale)
        self.f = a.focal / 10
        kp = np.zeros((h, w))
        kp[:2 * r + 1, :2 * r + 1] = ker
        self.kf = rfft2(np.roll(kp, (-r, -r), (0, 1)))
        self.s, self.aperture = (sx, sy), a.aperture

    def model(self, side, points):
        h, w = self.b.shape
        img = np.zeros((h, w))
        s = side * self.aperture * 9 * self.scale
        for lx, ly in points:
            x = self.W / 2 + (10 * self.s[0] - 9 * lx * self.aperture) * self.scale - self.x0
            y = self.H / 2 - (10 * self.s[1] - 9 * ly * self.aperture) * self.scale - self.y0
            img += np.outer(overlap(y, s, h), overlap(x, s, w))
        img *= self.b.sum() / len(points) / (s * s)
        return irfft2(rfft2(img) * self.kf, s=(h, w))

    def greedy(self, side, n):
        """Centres found one at a time where the residual holds the most."""
        r = self.b.copy()
        s = side * self.aperture * 9 * self.scale
        amp = self.b.sum() / n / (s * s)
        out = []
        for _ in range(n):
            f = uniform_filter(r, size=int(s), mode='constant')
            y, x = np.unravel_index(np.argmax(f), f.shape)
            r -= amp * np.outer(overlap(y + .5, s, r.shape[0]), overlap(x + .5, s, r.shape[1]))
            lx = -((x + .5 + self.x0 - self.W / 2) / self.scale - 10 * self.s[0]) / 9 / self.aperture
            ly = ((y + .5 + self.y0 - self.H / 2) / self.scale + 10 * self.s[1]) / 9 / self.aperture
            out.append((lx, ly))
        return out


def unpack(p, hexed):
    side, rest = p[0], p[1:]
    if hexed:
        pts = hexagon(rest[-2], rest[-1])
        rest = rest[:-2]
    else:
        pts = []
    return side, pts + [tuple(rest[2 * k:2 * k + 2]) for k in range(len(rest) // 2)]


def fit(data, side, points, hexed):
    free = points[7:] if hexed else points
    p = np.concatenate([[side], np.ravel(free)] + ([[0.1445, 0.1256]] if hexed else []))
    res = lambda p: np.concatenate([(d.model(*unpack(p, hexed)) - d.b).ravel() for d in data])
    sol = least_squares(res, p, x_scale=0.01)
    return sol.x, (sol.fun ** 2).sum()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('count', type=int)
    ap.add_argument('--aspect', type=float, default=1.0)
    ap.add_argument('--aperture', type=float, default=1.0)
    ap.add_argument('--angle', type=float, default=60.0)
    ap.add_argument('--focal', type=float, default=10.0)
    ap.add_argument('--size', type=int, default=4000)
    ap.add_argument('--renders', type=int, default=4)
    ap.add_argument('--side', type=float, default=0.125, help='starting square side')
    ap.add_argument('--table', help='a file of centres (x y per line) to start from')
    ap.add_argument('--starts', type=int, default=0, help='random restarts from the best')
    a = ap.parse_args()
    work = '/tmp/lens_fit'
    os.makedirs(work, exist_ok=True)
    # Shifts of the sphere: other pixels, other jitter.
    shifts = [(x * a.aperture * a.focal / 10, y * a.aperture * a.focal / 10) for x, y in
              [(0.0, 0.0), (0.0213, -0.0171), (0.0137, 0.0291), (-0.0253, -0.0077),
               (0.0311, 0.0059), (-0.0089, -0.0263)][:a.renders]]
    radius = 0.01 * a.aperture * a.focal / 10
    data = [Data(render(a, sx, sy, radius, work), sx, sy, a, radius) for sx, sy in shifts]
    if a.table:
        points = [tuple(map(float, l.split())) for l in open(a.table) if l.strip()]
    else:
        points = data[0].greedy(a.side, a.count)
    hexed = a.count > 7
    if hexed:
        near = lambda q: min(np.hypot(q[0] - x, q[1] - y) for x, y in hexagon(0.1445, 0.1256))
        free = sorted(points, key=near)[7:]
        points = hexagon(0.1445, 0.1256) + free
    p, sse = fit(data, a.side, points, hexed)
    side, pts = unpack(p, hexed)
    rng = np.random.default_rng(1)
    for _ in range(a.starts):
        moved = [np.array(q, dtype=float) for q in pts]
        for k in rng.choice(np.arange(7 if hexed else 0, len(pts)), size=2, replace=False):
            moved[k] += rng.normal(0, 0.03, 2)
        q, e = fit(data, side, [tuple(m) for m in moved], hexed)
        if e < sse:
            p, sse = q, e
            side, pts = unpack(p, hexed)
    bins = sum(d.b.size for d in data)
    print(f'count {a.count}: SSE {sse:.1f} over {bins} bins; side {side:.5f}')
    if hexed:
        print(f'hexagon spacing {p[-2]:.5f}, row {p[-1]:.5f}')
    for x, y in pts:
        print(f'{x:+.5f} {y:+.5f}')


if __name__ == '__main__':
    main()
