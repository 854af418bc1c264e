#!/usr/bin/env python3
"""POV-Ray's media quadrature against the integral it approximates, for one scene.

Renders the scene with povray as written (its own `method`, `intervals`, `samples`), and
again with every media block switched to `method 2 intervals 10 samples 10` (within 0.02%
of the integral on a test slab), and with penumbra; prints the image means and the largest
block difference. Usage: scripts/media_quadrature.py SCENE.pov [--size 160x120] [--spp 64]
Needs povray, numpy and OpenEXR; run from the repository (uses target/release/penumbra).
"""
import argparse, os, re, subprocess, tempfile
import numpy as np, OpenEXR, Imath

def read(path):
    f = OpenEXR.InputFile(path)
    dw = f.header()['dataWindow']
    w, h = dw.max.x - dw.min.x + 1, dw.max.y - dw.min.y + 1
    px = Imath.PixelType(Imath.PixelType.FLOAT)
    return np.stack([np.frombuffer(f.channel(c, px), dtype=np.float32).reshape(h, w)
                     for c in 'RGB'], -1)

def high(text):
    """Every media block's quadrature set to method 2, 10 intervals of 10 samples."""
    text = re.sub(r'\bmethod\s+[0-9.]+', '', text)
    text = re.sub(r'\bintervals\s+[0-9.]+', '', text)
    text = re.sub(r'\bsamples\s+[0-9.]+(\s*,\s*[0-9.]+)?', '', text)
    return re.sub(r'\bmedia\s*\{', 'media { method 2 intervals 10 samples 10 ', text)

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('scene')
    ap.add_argument('--size', default='160x120')
    ap.add_argument('--spp', default='64')
    a = ap.parse_args()
    w, h = a.size.split('x')
    folder = os.path.dirname(os.path.abspath(a.scene))
    inc = ['+L' + folder, '+L/usr/share/povray-3.7/include']
    tmp = tempfile.mkdtemp()
    hi_scene = os.path.join(tmp, 'high.pov')
    open(hi_scene, 'w').write(high(open(a.scene).read()))
    images = {}
    for name, scene in [('povray as written', a.scene), ('povray 10x10', hi_scene)]:
        out = os.path.join(tmp, name.replace(' ', '_') + '.exr')
        subprocess.run(['povray', '+I' + scene, '+O' + out, '+FE', '+W' + w, '+H' + h,
                        '-D', '-GA', '+A0.0', '+AM2', '+R3'] + inc, check=True,
                       capture_output=True)
        images[name] = read(out)
    out = os.path.join(tmp, 'penumbra.exr')
    subprocess.run(['target/release/penumbra', 'render', a.scene, '--output', out,
                    '--width', w, '--height', h, '--spp', a.spp, '--quiet',
                    '-L', folder], check=True)
    images['penumbra'] = read(out)
    ref = images['povray 10x10']
    for name, im in images.items():
        blocks = np.abs((im - ref).reshape(int(h) // 8, 8, int(w) // 8, 8, 3).mean((1, 3)))
        print(f'{name:18} mean {im.mean((0, 1)).round(5)}  '
              f'worst 8x8 block |d| against povray 10x10: {blocks.max():.4f}')

main()
