#!/usr/bin/env python3
"""Plots a demonstration: joint positions, the gripper, and the pick-and-place segment boundaries.

usage: plot_demo.py --csv demo.csv --segments segments.yaml --out demo.png [--title T]
(the CSV and YAML as `vrrw demos export` and `vrrw demos segment` write them)"""
import argparse
import csv
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.transforms as transforms  # noqa: E402
import yaml  # noqa: E402

LABEL_POINTS = 7  # font size of the segment names
ROW_POINTS = 10  # height of one row of segment names
GAP_PIXELS = 4  # least horizontal gap between two names in one row


def place_labels(fig, ax, segments):
    """Each segment's name above the axes, centred on its span, in the lowest row where it keeps GAP_PIXELS
    from every name already there (a short close_gripper between two motions gets a row of its own).
    Returns the texts and the number of rows."""
    renderer = fig.canvas.get_renderer()
    rows = []  # per row: the (left, right) pixel extents of the names placed in it
    texts = []
    for s in segments:
        centre = 0.5 * (s["start"] + s["end"])
        probe = ax.text(centre, 1.0, s["name"], transform=ax.get_xaxis_transform(), ha="center", va="bottom",
                        fontsize=LABEL_POINTS)
        box = probe.get_window_extent(renderer)
        probe.remove()
        row = next((k for k, taken in enumerate(rows)
                    if all(box.x1 + GAP_PIXELS <= left or right + GAP_PIXELS <= box.x0 for left, right in taken)),
                   len(rows))
        if row == len(rows):
            rows.append([])
        rows[row].append((box.x0, box.x1))
        lifted = transforms.offset_copy(ax.get_xaxis_transform(), fig=fig, y=2 + row * ROW_POINTS, units="points")
        texts.append(ax.text(centre, 1.0, s["name"], transform=lifted, ha="center", va="bottom",
                             fontsize=LABEL_POINTS))
    return texts, len(rows)


def draw(data, header, segments, title):
    """The figure of a demonstration; returns it with the segment names' texts."""
    n = (header.index("gripper") - 1) // 2 if "gripper" in header else (len(header) - 1) // 2
    t = [r[0] for r in data]
    fig, (joints, gripper) = plt.subplots(2, 1, sharex=True, figsize=(10, 6), gridspec_kw={"height_ratios": [3, 1]})
    for j in range(n):
        joints.plot(t, [r[1 + j] for r in data], label=header[1 + j], linewidth=1)
    if "gripper" in header:
        g = header.index("gripper")
        gripper.plot(t, [r[g] for r in data], color="k", linewidth=1)
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, s in enumerate(segments):
        for ax in (joints, gripper):
            ax.axvspan(s["start"], s["end"], color=colors[i % len(colors)], alpha=0.12)
            ax.axvline(s["start"], color="grey", linewidth=0.5)
    joints.set_ylabel("joint position (rad)")
    joints.legend(fontsize=7, loc="lower left")
    gripper.set_ylabel("gripper")
    gripper.set_xlabel("t (s)")
    title_text = fig.suptitle(title, y=0.995)
    fig.tight_layout()
    # the x extents are final now: place the names, then lower the axes' top below their rows and the title
    texts, rows = place_labels(fig, joints, segments)
    height = fig.get_figheight() * 72.0  # points
    title_points = title_text.get_window_extent(fig.canvas.get_renderer()).height * 72.0 / fig.dpi if title else 0
    top = 1.0 - (title_points + 6 + 2 + rows * ROW_POINTS) / height
    fig.subplots_adjust(top=min(fig.subplotpars.top, top))
    return fig, texts


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--csv", required=True)
    parser.add_argument("--segments", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--title", default="")
    args = parser.parse_args()
    with open(args.csv) as f:
        rows = list(csv.reader(f))
    header, data = rows[0], [[float(c) for c in r] for r in rows[1:] if r]
    with open(args.segments) as f:
        report = yaml.safe_load(f)
    segments = next(iter(report["robots"].values()))["segments"] if report.get("robots") else []
    fig, _ = draw(data, header, segments, args.title)
    tmp = args.out + ".tmp.png"
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
