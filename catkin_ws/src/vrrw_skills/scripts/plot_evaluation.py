#!/usr/bin/python3
"""Top view of a skill evaluation: plot_evaluation.py DIR reads DIR/tracks.json, writes DIR/top_view.png
(object starts, TCP paths, where each object ended, the place area)."""
import json
import os
import sys

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402


def main():
    directory = sys.argv[1]
    with open(os.path.join(directory, 'tracks.json')) as f:
        data = json.load(f)
    figure, axes = plt.subplots(figsize=(7, 7))
    for trial in data['trials']:
        colour = '#2a7' if trial['success'] else '#c33'
        if trial['tcp']:
            xs, ys = zip(*trial['tcp'])
            axes.plot(xs, ys, color=colour, alpha=0.35, linewidth=1)
        axes.plot(trial['x'], trial['y'], 'o', color=colour, markersize=5)
        axes.plot(*trial['end'], 'x', color=colour, markersize=6)
    axes.add_patch(plt.Circle(data['end'], data['radius'], color='#27c', fill=False, linewidth=2, label='place area'))
    axes.plot(*data['start'], 's', color='k', markersize=8, label='demonstrated start')
    axes.plot([], [], 'o', color='#2a7', label='start, success')
    axes.plot([], [], 'o', color='#c33', label='start, failed')
    axes.plot([], [], 'x', color='k', label='object at the end')
    axes.set_aspect('equal')
    axes.set_xlabel('x (m)')
    axes.set_ylabel('y (m)')
    axes.set_title(data['title'])
    axes.legend(loc='best', fontsize=8)
    axes.grid(alpha=0.3)
    figure.tight_layout()
    figure.savefig(os.path.join(directory, 'top_view.png'), dpi=100)


if __name__ == '__main__':
    main()
