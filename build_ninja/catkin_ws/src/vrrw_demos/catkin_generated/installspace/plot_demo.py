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
import yaml  # noqa: E402


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
    n = (header.index("gripper") - 1) // 2 if "gripper" in header else (len(header) - 1) // 2
    t = [r[0] for r in data]
    with open(args.segments) as f:
        report = yaml.safe_load(f)
    segments = next(iter(report["robots"].values()))["segments"] if report.get("robots") else []

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
        joints.text(0.5 * (s["start"] + s["end"]), joints.get_ylim()[1], s["name"], ha="center", va="bottom",
                    fontsize=7, rotation=20)
    joints.set_ylabel("joint position (rad)")
    joints.legend(fontsize=7, loc="lower left")
    gripper.set_ylabel("gripper")
    gripper.set_xlabel("t (s)")
    fig.suptitle(args.title, y=0.995)
    fig.tight_layout()
    tmp = args.out + ".tmp.png"
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
