"""Blender (bpy + NumPy) script: the mean radiance of each material's pixels in the Cycles and
the twinpath image (twinpath's material-id AOV says which pixels; glTF materials keep their order),
their relative difference, and the whole image's. Prints a markdown table.
    blender -b --factory-startup -P compare_materials.py -- CYCLES.exr TWINPATH.exr IDS.exr NAMES
NAMES: the comma-separated material names, in the scene's order (twinpath info).
"""
import sys

import bpy
import numpy as np

cycles_path, twin_path, ids_path, names = sys.argv[sys.argv.index("--") + 1:][:4]
names = names.split(",")


def load(path):
    img = bpy.data.images.load(path)
    w, h = img.size
    px = np.array(img.pixels[:], dtype=np.float64).reshape(h, w, 4)
    return px[::-1]  # Blender stores rows bottom to top


cyc, tw, ids = load(cycles_path), load(twin_path), load(ids_path)
# The material-id AOV (render --aov ids, channel id.material), -1 where the pixel centre sees
# nothing.
material = ids[:, :, 0]
lum = np.array([0.2126, 0.7152, 0.0722])
rows = []
for i, name in enumerate(names):
    mask = np.isfinite(material) & (np.rint(material) == i)
    if mask.sum() < 20:
        continue
    a = (cyc[:, :, :3][mask] @ lum).mean()
    b = (tw[:, :, :3][mask] @ lum).mean()
    rows.append((name, int(mask.sum()), a, b, (b - a) / a if a > 0 else float("nan")))
a = (cyc[:, :, :3] @ lum).mean()
b = (tw[:, :, :3] @ lum).mean()
print("| material | pixels | Cycles | twinpath | twinpath / Cycles - 1 |")
print("|---|---|---|---|---|")
for name, n, x, y, d in rows:
    print(f"| {name} | {n} | {x:.4f} | {y:.4f} | {d:+.1%} |")
print(f"| whole image | {cyc.shape[0] * cyc.shape[1]} | {a:.4f} | {b:.4f} | {(b - a) / a:+.1%} |")
# 32 x 32 tiles: the relative difference of their mean luminance, median and worst.
h, w = cyc.shape[:2]
tiles = []
for y in range(0, h - 31, 32):
    for x in range(0, w - 31, 32):
        ta = (cyc[y:y + 32, x:x + 32, :3] @ lum).mean()
        tb = (tw[y:y + 32, x:x + 32, :3] @ lum).mean()
        if ta > 0:
            tiles.append(abs(tb - ta) / ta)
tiles.sort()
print(f"| 32x32 tiles: median, worst abs difference | {len(tiles)} | | | "
      f"{tiles[len(tiles) // 2]:.1%}, {tiles[-1]:.1%} |")
