#!/usr/bin/python3
"""Draws one panel per joint, demonstration and DMP trajectories over time (like Fig. 6 of the paper).

Reads JSON on stdin from `vrrw_dmp plot` (which reads and checks the CSVs with the project's one CSV
reader): {"out": PNG, "title": str, "joints": [names], "series": [{"label", "t": [...], "q": [[...] per joint]}]}.
"""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    data = json.load(sys.stdin)
    joints = data["joints"]
    columns = 3 if len(joints) > 4 else min(2, len(joints))
    rows = math.ceil(len(joints) / columns)
    figure, axes = plt.subplots(rows, columns, figsize=(4.2 * columns, 2.8 * rows), squeeze=False, sharex=True)
    styles = [dict(color="black", linewidth=2.2, alpha=0.55)] + [
        dict(linestyle="--", linewidth=1.6, color=color) for color in ("tab:red", "tab:blue", "tab:green", "tab:orange")
    ]
    for index, name in enumerate(joints):
        axis = axes[index // columns][index % columns]
        for number, series in enumerate(data["series"]):
            axis.plot(series["t"], series["q"][index], label=series["label"], **styles[min(number, len(styles) - 1)])
        axis.set_title(name, fontsize=10)
        axis.set_ylabel("rad")
        axis.grid(True, alpha=0.3)
    for index in range(len(joints), rows * columns):
        axes[index // columns][index % columns].axis("off")
    for column in range(columns):
        axes[rows - 1][column].set_xlabel("time (s)")
    axes[0][0].legend(fontsize=8, loc="best")
    if data.get("title"):
        figure.suptitle(data["title"])
    figure.tight_layout()
    save_whole(figure, data["out"])


def save_whole(figure, out):
    """Saves beside the target and renames when complete, so a failed plot never leaves a partial file."""
    partial = f"{out}.partial-{os.getpid()}"
    extension = os.path.splitext(out)[1][1:].lower() or "png"
    try:
        figure.savefig(partial, dpi=110, format=extension)
        os.replace(partial, out)
    finally:
        if os.path.exists(partial):
            os.remove(partial)


if __name__ == "__main__":
    try:
        main()
    except (OSError, ValueError, KeyError) as error:
        print(f"plot_dmp.py: {error}", file=sys.stderr)
        sys.exit(1)
