# %% [markdown]
# # Error against time: ss, lbl, mdom and the path tracer on one scene
#
# Renders the bundled sphere (or the scene given as the first argument) with
# every fast method and with the path tracer at growing sample counts, measures
# each image against a long path-traced truth (relative RMSE over the pixels
# the object covers), and plots error against time. Cells run in Jupyter or
# VS Code; as a script:
#
#     PYTHONPATH=build/python python3 examples/compare_methods.py [SCENE] [-o PLOT.png]

# %%
import argparse
import shutil
import tempfile
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import lucent

parser = argparse.ArgumentParser(description=__doc__)
root = Path(__file__).resolve().parent.parent
parser.add_argument("scene", nargs="?", default=str(root / "models" / "sphere.json"))
parser.add_argument("-o", "--output", default="compare_methods.png")
parser.add_argument("--size", type=int, default=96)
args, _ = parser.parse_known_args()

# %% Work on a copy, so that the sample files land beside it and not in the source tree.
work = Path(tempfile.mkdtemp(prefix="lucent-compare-"))
source = Path(args.scene)
for f in source.parent.iterdir():
    if f.is_file():
        shutil.copy(f, work / f.name)
scene = lucent.load_scene(str(work / source.name))
lucent.preprocess(scene, quality="default")
size = dict(width=args.size, height=args.size)

# %% The truth: the path tracer with many paths per pixel.
truth, report = lucent.render(scene, method="path", options={"samples": 1024}, seed=7, **size)
print(f"truth: path, 1024 paths per pixel, {report['seconds']:.1f} s")
inside = truth.sum(axis=2) > 0


def error(image):
    """Relative RMSE against the truth over the pixels the object covers."""
    return float(np.sqrt(np.mean((image[inside] - truth[inside]) ** 2)) / np.sqrt(np.mean(truth[inside] ** 2)))


# %% Each method once, the path tracer at growing sample counts (another seed).
points = {}
available = {m["name"] for m in lucent.methods() if not m["unavailable"]}
for method in ["ss", "lbl", "mdom"]:
    if method in available:
        image, report = lucent.render(scene, method=method, **size)
        points[method] = [(report["seconds"], error(image))]
        print(f"{method}: {points[method][0][1]:.1%} in {report['seconds']:.2f} s")
points["path"] = []
for samples in [4, 16, 64, 256]:
    image, report = lucent.render(scene, method="path", options={"samples": samples}, seed=1, **size)
    points["path"].append((report["seconds"], error(image)))
    print(f"path {samples}: {points['path'][-1][1]:.1%} in {report['seconds']:.2f} s")

# %% The plot: error against seconds, both on log scales.
fig, ax = plt.subplots(figsize=(6, 4))
for method, pts in points.items():
    t, e = zip(*pts)
    ax.plot(t, e, "o-" if len(pts) > 1 else "o", label=method)
ax.set_xscale("log")
ax.set_yscale("log")
ax.set_xlabel("seconds per image")
ax.set_ylabel("relative RMSE against path (1024 paths)")
ax.set_title(f"{source.name}, {args.size}x{args.size}")
ax.legend()
fig.tight_layout()
fig.savefig(args.output, dpi=120)
print(f"wrote {args.output}")
shutil.rmtree(work)
