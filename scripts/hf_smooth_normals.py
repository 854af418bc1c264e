#!/usr/bin/env python3
"""Smooth height-field normals, POV-Ray against penumbra, at the grid points of a 5 x 5
function height field (heights 0.5 + 0.3 x^2 - 0.2 y + 0.25 x y).

Each renderer draws the field from straight above (orthographic, 241 x 241) lit by a
parallel light from three directions with `diffuse 1`, so a pixel's value is N.L; the three
images give N at every grid point, printed as the surface's slopes (-N.x / N.y, -N.z / N.y)
beside the slopes of central differences. Usage: scripts/hf_smooth_normals.py (from the
repository; needs povray, numpy, Pillow and OpenEXR; uses target/release/penumbra).
"""
import os, subprocess, tempfile
import numpy as np, OpenEXR, Imath

LIGHTS = {'y': (0, 1, 0), 'x': (0.5, 0.8660254, 0), 'z': (0, 0.8660254, 0.5)}
SCENE = """#version 3.7;
global_settings {{ assumed_gamma 1 }}
camera {{ orthographic location <0.5, 5, 0.5> look_at <0.5, 0, 0.5> right x*1.2 up z*1.2 }}
light_source {{ <{l}>*1000 rgb 1 parallel point_at 0 }}
height_field {{ function 5, 5 {{ 0.5 + 0.3*x*x - 0.2*y + 0.25*x*y }} smooth
  pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 1 }} }}
"""

def exr(path):
    f = OpenEXR.InputFile(path)
    dw = f.header()['dataWindow']
    w, h = dw.max.x - dw.min.x + 1, dw.max.y - dw.min.y + 1
    px = Imath.PixelType(Imath.PixelType.FLOAT)
    return np.frombuffer(f.channel('R', px), dtype=np.float32).reshape(h, w).astype(float)

def render(tmp):
    images = {'povray': {}, 'penumbra': {}}
    for k, l in LIGHTS.items():
        scene = os.path.join(tmp, f'{k}.pov')
        open(scene, 'w').write(SCENE.format(l=','.join(map(str, l))))
        ref = os.path.join(tmp, f'{k}-ref.exr')
        subprocess.run(['target/release/penumbra', 'reference', scene, '--output', ref,
                        '--width', '241', '--height', '241', '--supersample', '2'],
                       check=True, capture_output=True)
        images['povray'][k] = exr(ref)
        out = os.path.join(tmp, f'{k}-pen.exr')
        subprocess.run(['target/release/penumbra', 'render', scene, '--width', '241',
                        '--height', '241', '--spp', '16', '--output', out],
                       check=True, capture_output=True)
        images['penumbra'][k] = exr(out)
    return images

def at(img, x, z):
    # The image's columns run along -x (the camera looks down), its rows along -z.
    px = (1.1 - x) / 1.2 * 241 - 0.5
    py = (1.1 - z) / 1.2 * 241 - 0.5
    x0, y0 = int(np.floor(px)), int(np.floor(py))
    fx, fy = px - x0, py - y0
    return (img[y0, x0] * (1 - fx) * (1 - fy) + img[y0, x0 + 1] * fx * (1 - fy)
            + img[y0 + 1, x0] * (1 - fx) * fy + img[y0 + 1, x0 + 1] * fx * fy)

def slopes(images, x, z):
    ny = at(images['y'], x, z)
    nx = (at(images['x'], x, z) - 0.8660254 * ny) / 0.5
    nz = (at(images['z'], x, z) - 0.8660254 * ny) / 0.5
    return -nx / ny, -nz / ny

def main():
    f = lambda x, y: 0.5 + 0.3 * x * x - 0.2 * y + 0.25 * x * y
    height = lambda i, j: f(min(max(i, 0), 4) / 4, 1 - min(max(j, 0), 4) / 4)
    with tempfile.TemporaryDirectory() as tmp:
        images = render(tmp)
    print('i j | POV-Ray slope x z | penumbra slope x z | central differences x z')
    for j in range(5):
        for i in range(5):
            x, z = min(max(i / 4, 0.004), 0.996), min(max(j / 4, 0.004), 0.996)
            i0, i1, j0, j1 = max(i - 1, 0), min(i + 1, 4), max(j - 1, 0), min(j + 1, 4)
            cx = (height(i1, j) - height(i0, j)) / (i1 - i0) * 4
            cz = (height(i, j1) - height(i, j0)) / (j1 - j0) * 4
            p, q = slopes(images['povray'], x, z), slopes(images['penumbra'], x, z)
            print(f'{i} {j} | {p[0]:6.3f} {p[1]:6.3f} | {q[0]:6.3f} {q[1]:6.3f} | {cx:6.3f} {cz:6.3f}')

if __name__ == '__main__':
    main()
