#!/usr/bin/env python3
"""Plots of a demo report directory (run_demo.py calls draw(); also usable alone: plot_demo.py DIR).

joints.png: the six arm joints of the demonstration, the replay and the shown DMP trials, with the
demonstration's instruction boundaries (the paper's Fig. 6); top_view.png: TCP paths and drill poses of
every run seen from above; strips.png: the rviz frames at the six instruction boundaries, one row per run
(the paper's Fig. 5).
"""
import csv
import glob
import math
import os
import sys

import matplotlib
matplotlib.use('Agg')
import matplotlib.image  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

INSTRUCTIONS = ['move_to_near_pick', 'move_to_pick', 'close_gripper', 'back_to_near_pick', 'move_to_final',
                'open_gripper']
STYLE = {'demonstration': ('black', '-', 2.0), 'replay': ('tab:orange', '--', 1.5)}


def read(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    return {name: [float(r[i]) if name != 'name' else r[i] for r in body] for i, name in enumerate(header)}


def runs(out):
    names = [os.path.basename(p)[:-len('_joints.csv')] for p in glob.glob(os.path.join(out, 'data', '*_joints.csv'))]
    trials = sorted((n for n in names if n.startswith('trial_')), key=lambda n: int(n.split('_')[1]))
    return [n for n in ('demonstration', 'replay') if n in names] + trials


def style(run, index):
    return STYLE.get(run, (plt.cm.viridis(0.15 + 0.7 * (index % 6) / 6), '-', 1.0))


def draw_joints(out, names):
    shown = [n for n in names if not n.startswith('trial_') or
             os.path.exists(os.path.join(out, 'frames', f'{n}_1.png'))]
    fig, axes = plt.subplots(3, 2, figsize=(12, 8), sharex=True)
    joints = None
    for index, run in enumerate(shown):
        data = read(os.path.join(out, 'data', f'{run}_joints.csv'))
        joints = [k for k in data if k != 't']
        color, line, width = style(run, index)
        for axis, joint in zip(axes.flat, joints):
            axis.plot(data['t'], data[joint], color=color, linestyle=line, linewidth=width, label=run)
    if joints is None:
        return
    segments = read(os.path.join(out, 'data', 'demonstration_segments.csv'))
    for axis, joint in zip(axes.flat, joints):
        for end in segments['end'][:-1]:
            axis.axvline(end, color='grey', linewidth=0.6, linestyle=':')
        axis.set_title(joint, fontsize=9)
        axis.set_ylabel('rad')
    for axis in axes[-1]:
        axis.set_xlabel('s from the start of the run')
    axes[0][0].legend(fontsize=7)
    fig.suptitle('Joints: demonstration, replay and DMP trials (dotted: the demonstration\'s instruction ends)')
    fig.tight_layout()
    fig.savefig(os.path.join(out, 'joints.png'), dpi=80)
    plt.close(fig)


def draw_top_view(out, names):
    fig, axis = plt.subplots(figsize=(7, 7))
    for index, run in enumerate(names):
        track = read(os.path.join(out, 'data', f'{run}_track.csv'))
        if not track['t']:
            continue
        color, line, width = style(run, index)
        axis.plot(track['tcp_x'], track['tcp_y'], color=color, linestyle=line, linewidth=width,
                  label=run if not run.startswith('trial_') or index < 4 else None)
        for k, marker in ((0, 'o'), (-1, 's')):
            x, y, yaw = track['object_x'][k], track['object_y'][k], track['object_yaw'][k]
            axis.plot(x, y, marker, color=color, markersize=4)
            axis.plot([x, x + 0.04 * math.cos(yaw)], [y, y + 0.04 * math.sin(yaw)], color=color, linewidth=0.8)
    demo = os.path.join(out, 'data', 'demonstration_track.csv')
    if os.path.exists(demo):
        track = read(demo)
        axis.add_patch(plt.Circle((track['object_x'][-1], track['object_y'][-1]), 0.03, fill=False, color='red',
                                  linestyle='--', label='final area (3 cm)'))
    axis.set_aspect('equal')
    axis.set_xlabel('x (m)')
    axis.set_ylabel('y (m)')
    axis.set_title('Top view: TCP paths, drill start (o) and end (s), chuck direction')
    axis.legend(fontsize=7, loc='best')
    fig.tight_layout()
    fig.savefig(os.path.join(out, 'top_view.png'), dpi=80)
    plt.close(fig)


def draw_strips(out, names):
    rows = [n for n in names if os.path.exists(os.path.join(out, 'frames', f'{n}_1.png'))]
    if not rows:
        return
    fig, axes = plt.subplots(len(rows), 6, figsize=(15, 2.3 * len(rows)), squeeze=False)
    for r, run in enumerate(rows):
        for c in range(6):
            axis = axes[r][c]
            axis.set_xticks([])
            axis.set_yticks([])
            path = os.path.join(out, 'frames', f'{run}_{c + 1}.png')
            if os.path.exists(path):
                image = matplotlib.image.imread(path)
                axis.imshow(image[70:-40, 40:-40])  # the 3D view without rviz's tool and status bars
            if r == 0:
                axis.set_title(INSTRUCTIONS[c].replace('_', ' '), fontsize=9)
            if c == 0:
                axis.set_ylabel(run.replace('_', ' '), fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(out, 'strips.png'), dpi=70)
    plt.close(fig)


def draw(out):
    names = runs(out)
    draw_joints(out, names)
    draw_top_view(out, names)
    draw_strips(out, names)


if __name__ == '__main__':
    draw(sys.argv[1] if len(sys.argv) > 1 else 'demo_report')
