"""Plots docs/plots/time_vs_faces.csv (written by measure_time_vs_faces.sh) as
docs/images/time-vs-faces.png: the median time against the face count, log-log, for Prism and
OpenSubdiv's runner, whole process (OBJ in, OBJ out) and refinement alone.
Needs matplotlib (pip install matplotlib)."""
import csv
import statistics
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = Path(__file__).parent
rows = defaultdict(list)
with open(here / "time_vs_faces.csv") as f:
    for r in csv.DictReader(f):
        rows[(r["tool"], r["what"])].append((int(r["faces"]), float(r["seconds"])))

fig, ax = plt.subplots(figsize=(7, 4.5), dpi=110)
style = {
    ("prism", "whole"): ("Prism, OBJ to OBJ", "tab:blue", "-"),
    ("opensubdiv", "whole"): ("OpenSubdiv 3.5 runner, OBJ to OBJ", "tab:orange", "-"),
    ("prism", "refine"): ("Prism, refinement alone", "tab:blue", "--"),
    ("opensubdiv", "refine"): ("OpenSubdiv, refinement alone", "tab:orange", "--"),
}
for key, (label, color, line) in style.items():
    by_faces = defaultdict(list)
    for faces, s in rows.get(key, []):
        by_faces[faces].append(s)
    xs = sorted(by_faces)
    ys = [statistics.median(by_faces[x]) for x in xs]
    ax.plot(xs, ys, line, color=color, marker="o", label=label)
ax.set_xscale("log")
ax.set_yscale("log")
ax.set_xlabel("input faces (quad torus)")
ax.set_ylabel("seconds (median)")
ax.set_title("Catmull–Clark level 1 on a 2-core machine")
ax.grid(True, which="both", alpha=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(here.parent / "images" / "time-vs-faces.png")
